/* suite_recombine.c - the quad recombination suite: matching and Blossom-Quad. */
#include "suites.h"
#include "quad/quad_tests.h"

Suite *quad_recombine_suite(void)
{
    Suite *s = suite_create("quad_recombine");
    suite_add_tcase(s, quad_matching_tcase());
    suite_add_tcase(s, quad_recombine_tcase());
    return s;
}
