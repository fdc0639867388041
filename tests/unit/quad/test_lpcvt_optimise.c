/* test_lpcvt_optimise.c - boundary discretisation, initial sites and the L-BFGS optimiser. */
#include "quad/quad_tests.h"

TCase *quad_lpcvt_optimise_tcase(void)
{
    return tcase_create("lpcvt_optimise");
}
