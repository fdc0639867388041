/* main.c - runs every Check suite of the unit tests; exit status 0 only if all pass. */
#include <stdlib.h>
#include "suites.h"

int main(void)
{
    SRunner *sr = srunner_create(geom_suite());
    int failed;
    srunner_add_suite(sr, delaunay_suite());
    srunner_add_suite(sr, delaunay3_suite());
    srunner_add_suite(sr, io_suite());
    srunner_add_suite(sr, api_suite());
    srunner_add_suite(sr, refine_suite());
    srunner_add_suite(sr, dual_suite());
    srunner_add_suite(sr, surface3_suite());
    srunner_add_suite(sr, quad_recombine_suite());
    srunner_add_suite(sr, quad_suite());
    srunner_add_suite(sr, generate3_suite());
    srunner_add_suite(sr, dual3_suite());
    srunner_add_suite(sr, support_suite());
    srunner_run_all(sr, CK_NORMAL);
    failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
