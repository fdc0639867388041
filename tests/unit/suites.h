/* suites.h - one Check suite per module; tests/unit/main.c runs them all. */
#ifndef CVMTEST_SUITES_H
#define CVMTEST_SUITES_H
#include <check.h>

Suite *geom_suite(void);     /* tests/unit/geom/suite.c */
Suite *delaunay_suite(void); /* tests/unit/delaunay/suite.c */
Suite *delaunay3_suite(void); /* tests/unit/delaunay3/suite.c */
Suite *io_suite(void);       /* tests/unit/io/suite.c */
Suite *api_suite(void);      /* tests/unit/api/suite.c */
Suite *refine_suite(void);   /* tests/unit/refine/suite.c */
Suite *dual_suite(void);     /* tests/unit/dual/suite.c */
Suite *surface3_suite(void); /* tests/unit/surface3/suite.c */
Suite *quad_recombine_suite(void); /* tests/unit/quad/suite_recombine.c */
Suite *quad_suite(void);     /* tests/unit/quad/suite.c */
Suite *generate3_suite(void); /* tests/unit/generate3/suite.c */
Suite *dual3_suite(void);    /* tests/unit/dual3/suite.c */
Suite *support_suite(void);  /* tests/unit/support/test_support.c: the test helpers themselves */

#endif
