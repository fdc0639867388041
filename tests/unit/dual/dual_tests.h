/* dual_tests.h - the TCases of the dual suite. */
#ifndef CVMTEST_DUAL_TESTS_H
#define CVMTEST_DUAL_TESTS_H
#include <check.h>

TCase *dual_power_side_tcase(void); /* lib/dual/power_side.c */
TCase *dual_regular_tcase(void);    /* lib/delaunay/regular.c via cvm_mesh_set_weights */
TCase *dual_api_tcase(void);        /* lib/api/dual.c */
TCase *dual_quality_tcase(void);    /* lib/dual/quality.c, lib/api/dual_quality.c */
TCase *dual_cells_tcase(void);      /* lib/dual/cells.c, lib/api/dual_cells.c */
TCase *dual_fv_tcase(void);         /* the finite-volume dual: lib/dual/cells.c, lib/api/dual_cells.c */
TCase *dual_optimise_tcase(void);   /* lib/api/optimise.c, lib/dual/optimise*.c, lib/dual/merge.c */
TCase *dual_prepass_tcase(void);    /* lib/dual/prepass.c (CVM_OPT_DUAL_PREPASS) */

/* Helpers (util.c). */
#include <stddef.h>
#include <stdint.h>
#include "cvmesh.h"

/* The unit square [0,1]^2 (4 segments), triangulated and refined with
 * CVM_ALGO_FRONTAL at uniform size h. */
cvm_mesh *dtest_refined_square(double h);

/* A mesh's arrays, copied through the public API (caller frees with dtest_free). */
typedef struct dtest_mesh {
    size_t nv, nt, ne, nseg;
    double *xy;        /* 2*nv */
    cvm_index *tri;    /* 3*nt */
    cvm_index *nbr;    /* 3*nt */
    cvm_index *edge;   /* 2*ne */
    cvm_index *seg;    /* 2*nseg, sorted pairs */
    double *w;         /* nv */
} dtest_mesh;
void dtest_get(cvm_mesh *m, dtest_mesh *d);
void dtest_free(dtest_mesh *d);
/* Assert that two fetched meshes have the same counts and bit-identical
 * points, weights and triangles. */
void dtest_assert_identical(const dtest_mesh *a, const dtest_mesh *b);

/* 1 when (a, b) is an output segment of d. */
int dtest_is_segment(const dtest_mesh *d, cvm_index a, cvm_index b);

/* Number of interior non-segment edges of d failing the exact power test
 * (cvm__power2d > 0) under weights w (nv entries). */
size_t dtest_power_violations(const dtest_mesh *d, const double *w);

/* splitmix64 uniform in [0, 1). */
double dtest_uniform(uint64_t *state);

#endif
