/*
 * fuzz_run.h - the steps the PSLG-driven fuzz targets (fuzz_refine,
 * fuzz_optimise) share: a mesh from a fuzz_pslg, triangulation with its failure
 * contract, the mesh checks, measures and allocation. Every helper aborts
 * through FUZZ_REQUIRE (reported as "fuzz_run") when a requirement fails, so
 * the fuzzer records the input. Single-threaded, like the targets.
 */
#ifndef CVM_FUZZ_RUN_H
#define CVM_FUZZ_RUN_H

#include <stddef.h>

#include "cvmesh.h"
#include "fuzz_pslg.h"
#include "support/mesh_oracle.h"

/* malloc(n + 1) (never NULL for n = 0); aborts when out of memory. The caller frees. */
void *fuzz_alloc(size_t n);

/* cvm_mesh_get_measure(which); aborts unless it returns CVM_OK. */
double fuzz_measure(cvm_mesh *m, cvm_measure which);

/* A new mesh holding g (fuzz_pslg_set()); aborts on any failure. The caller frees it. */
cvm_mesh *fuzz_pslg_mesh(const fuzz_pslg *g);

/* cvm_mesh_triangulate(m). A failure is allowed only as an error status with a
 * message (aborts otherwise); the status is returned either way. */
cvm_status fuzz_triangulate(cvm_mesh *m);

/* cvm_mesh_check() must accept m; with e, so must the independent oracle
 * (cvmtest_mesh_validate()) under those expectations. */
void fuzz_validate(cvm_mesh *m, const cvmtest_expect *e);

#endif
