/* suite.c - the geom suite: one TCase per source file under test. */
#include "suites.h"
#include "geom/geom_tests.h"

Suite *geom_suite(void)
{
    Suite *s = suite_create("geom");
    suite_add_tcase(s, geom_expansion_tcase());
    suite_add_tcase(s, geom_exact_det_tcase());
    suite_add_tcase(s, geom_orient2d_tcase());
    suite_add_tcase(s, geom_incircle_tcase());
    suite_add_tcase(s, geom_power2d_tcase());
    suite_add_tcase(s, geom_orient3d_tcase());
    suite_add_tcase(s, geom_insphere_tcase());
    suite_add_tcase(s, geom_sos_tcase());
    suite_add_tcase(s, geom_power3d_tcase());
    suite_add_tcase(s, geom_sos3d_tcase());
    suite_add_tcase(s, geom_construct_tcase());
    suite_add_tcase(s, geom_measure_tcase());
    suite_add_tcase(s, geom_tet_centre_tcase());
    return s;
}
