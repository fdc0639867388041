/* suite.c - the geom suite: one TCase per source file under test. */
#include "suites.h"

Suite *geom_suite(void)
{
    Suite *s = suite_create("geom");
    return s;
}
