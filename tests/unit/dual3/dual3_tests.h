/* dual3_tests.h - TCases of the dual3 suite (tests/unit/dual3/suite.c). */
#ifndef CVMTEST_DUAL3_TESTS_H
#define CVMTEST_DUAL3_TESTS_H
#include <check.h>

TCase *dual3_optimise_tcase(void); /* test_optimise3.c: cvm_mesh_optimise_dual3() */

TCase *dual3_merge_tcase(void);    /* test_merge3.c: merged 3D dual cells */

TCase *dual3_own_mesh_tcase(void); /* test_own_mesh.c: cvm_mesh_set_tetrahedra(), .ele */

#endif
