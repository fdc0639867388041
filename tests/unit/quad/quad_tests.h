/* quad_tests.h - the TCases of the quad suite (metric field, Lp-CVT energy and optimiser). */
#ifndef CVMTEST_QUAD_TESTS_H
#define CVMTEST_QUAD_TESTS_H
#include <check.h>
#include <stddef.h>
#include "cvmesh.h"

TCase *quad_dunavant_tcase(void);
TCase *quad_metric_tcase(void);
TCase *quad_lpcvt_energy_tcase(void);
TCase *quad_lpcvt_optimise_tcase(void);

/* The boundary of the box [x0, x1] x [y0, y1] with n pieces a side, counter-clockwise from
 * (x0, y0), into xy (8 n values). */
void qtest_box(double *xy, double x0, double y0, double x1, double y1, int n);
/* A deterministic uniform double in [0, 1) from *state (splitmix64). */
double qtest_uniform(unsigned long long *state);

#endif
