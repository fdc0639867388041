/* suite.c - the surface3 suite: 3D surface readers, validation and TetGen recovery. */
#include "suites.h"
#include "surface3/surface3_tests.h"

Suite *surface3_suite(void)
{
    Suite *s = suite_create("surface3");
    suite_add_tcase(s, surface3_read_tcase());
    suite_add_tcase(s, surface3_faults_tcase());
    suite_add_tcase(s, surface3_validate_tcase());
    suite_add_tcase(s, surface3_tetgen_tcase());
    return s;
}
