/* suite.c - the delaunay3 suite: one TCase per concern of the 3D engine. */
#include "suites.h"
#include "delaunay3/delaunay3_tests.h"

Suite *delaunay3_suite(void)
{
    Suite *s = suite_create("delaunay3");
    suite_add_tcase(s, delaunay3_build_tcase());
    suite_add_tcase(s, delaunay3_input_tcase());
    suite_add_tcase(s, delaunay3_weighted_tcase());
    suite_add_tcase(s, delaunay3_oom_tcase());
    suite_add_tcase(s, delaunay3_par_tcase());
    return s;
}
