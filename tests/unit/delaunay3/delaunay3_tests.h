/* delaunay3_tests.h - the TCases of the delaunay3 suite and their shared helpers. */
#ifndef CVMTEST_DELAUNAY3_TESTS_H
#define CVMTEST_DELAUNAY3_TESTS_H
#include <check.h>
#include <stddef.h>
#include <stdint.h>

#include "delaunay3/delaunay3_internal.h"

TCase *delaunay3_build_tcase(void);    /* test_build3.c: random, lattices, spheres, determinism */
TCase *delaunay3_input_tcase(void);    /* test_input3.c: duplicates, degenerate and bad input, check */
TCase *delaunay3_weighted_tcase(void); /* test_weighted3.c: regular tetrahedralisation */
TCase *delaunay3_oom_tcase(void);      /* test_oom3.c: out of memory at every allocation */
TCase *delaunay3_par_tcase(void);      /* test_par3.c: parallel insertion, same output for any thread count */

/* Build (weights w may be NULL) on a fresh store over ctx, assert CVM_OK and
 * that cvm__tet3_check() passes; returns the canonical tetrahedra (caller
 * frees with free()), their count in *nt. */
int32_t *d3test_build(cvm__tet3 *T, cvm__ctx *ctx, const double *xyz, const double *w, size_t n,
                      uint64_t seed, size_t *nt);
/* Uniform random points in [0,1)^3 from a fixed LCG stream. */
void d3test_random(double *xyz, size_t n, uint64_t seed);
/* The body-centred cubic lattice: corners (2i, 2j, 2k), i,j,k < k_, and cell
 * centres (2i+1, 2j+1, 2k+1) for i,j,k < k_ - 1; returns the count. */
size_t d3test_bcc(double *xyz, int k);
/* V - E + F - T of the tetrahedra (V = distinct vertices used). */
long d3test_euler(const int32_t *tets, size_t nt);

#endif
