/* suite.c - the delaunay suite: one TCase per source file under test. */
#include "suites.h"
#include "delaunay/delaunay_tests.h"

Suite *delaunay_suite(void)
{
    Suite *s = suite_create("delaunay");
    suite_add_tcase(s, delaunay_build_tcase());
    suite_add_tcase(s, delaunay_cdt_tcase());
    suite_add_tcase(s, delaunay_insert_tcase());
    suite_add_tcase(s, delaunay_pslg_build_tcase());
    return s;
}
