/* delaunay_tests.h - the TCases of the delaunay suite. */
#ifndef CVMTEST_DELAUNAY_TESTS_H
#define CVMTEST_DELAUNAY_TESTS_H
#include <check.h>
#include "cvmesh.h"

TCase *delaunay_build_tcase(void);
TCase *delaunay_cdt_tcase(void);
TCase *delaunay_insert_tcase(void);
TCase *delaunay_pslg_build_tcase(void);

/* Fetch the triangles of m (caller frees), count in *nt. */
cvm_index *dtest_triangles(cvm_mesh *m, size_t *nt);
/* Canonical form of a triangle list (each rotated to start at its smallest id,
 * then sorted), so two meshes compare as sets. */
void dtest_canonical(cvm_index *tri, size_t nt);
/* Uniform random points in the unit square from a fixed LCG stream. */
void dtest_random_points(double *xy, size_t n, unsigned long seed);

#endif
