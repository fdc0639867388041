/* suite.c - the io suite: one TCase per source file under test. */
#include "suites.h"

Suite *io_suite(void)
{
    Suite *s = suite_create("io");
    return s;
}
