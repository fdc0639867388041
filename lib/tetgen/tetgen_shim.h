/*
 * tetgen_shim.h - boundary recovery of a 3D surface by TetGen 1.5 (H. Si,
 * "TetGen, a Delaunay-based quality tetrahedral mesh generator", ACM TOMS
 * 41(2), 2015), the optional AGPL-3+ component of cvmesh. The library is built
 * with it when TETGEN=1 (the default when /usr/include/tetgen.h exists); with
 * TETGEN=0 the function below returns CVM_E_UNSUPPORTED. The .cxx file is the
 * only C++ in the tree; this header is plain C.
 */
#ifndef CVM_TETGEN_SHIM_H
#define CVM_TETGEN_SHIM_H

#include <stddef.h>
#include <stdint.h>
#include "common/surf3.h"

#ifdef __cplusplus
extern "C" {
#endif

/* A tetrahedralisation of the inside of a surface, arrays allocated through
 * the ctx. Orientation: cvm__orient3d(p[t0], p[t1], p[t2], p[t3]) > 0 for
 * every tetrahedron (t0..t3). */
typedef struct cvm__tet3_out {
    double *xyz;              /* 3*np: the surface's points first, in order, then Steiner points */
    size_t np;
    size_t n_input;           /* points that came from the surface */
    size_t n_steiner_boundary;/* Steiner points on boundary faces (0 when the boundary was kept) */
    size_t n_steiner_interior;/* Steiner points inside the domain */
    int32_t *tet;             /* 4*ntet point indices */
    size_t ntet;
    double *tattr;            /* ntet region attributes, or NULL when the surface has no regions */
    int32_t *face;            /* 3*nface: boundary and internal-facet triangles */
    int32_t *fmark;           /* nface: the marker of the facet each lies in */
    size_t nface;
    int boundary_kept;        /* 1 when TetGen kept the boundary unsplit (switch Y) */
} cvm__tet3_out;

/* 1 when this build links TetGen. */
int cvm__tetgen_available(void);

/* Tetrahedralise the inside of s (a surface that passed cvm__surf3_validate)
 * with TetGen's boundary recovery ("pYQ", plus "A" when s has regions; no
 * quality refinement, region max volumes ignored), keeping the boundary
 * unsplit; when TetGen cannot, it retries without Y and reports the boundary
 * Steiner points. Holes and regions of s are passed on. Returns CVM_OK,
 * CVM_E_UNSUPPORTED (a build without TetGen; a polygon of more than INT32_MAX
 * corners), CVM_E_NOMEM, CVM_E_INPUT_INTERSECTING (TetGen found faces that
 * intersect or overlap: its codes 3 and 5), CVM_E_INPUT_DEGENERATE (a feature
 * below its tolerance or a degenerate input: codes 4 and 10), CVM_E_INTERNAL
 * (code 2, another exception, or an output that fails the checks). TetGen
 * allocates with new[], outside the ctx allocator, and may print to stdout on
 * errors. out is empty on error. */
cvm_status cvm__tetgen_recover(cvm__ctx *ctx, const cvm__surf3 *s, cvm__tet3_out *out);

void cvm__tet3_out_free(cvm__ctx *ctx, cvm__tet3_out *out);

/* Check a filled out (indices in range), turn every tetrahedron positive by
 * the exact cvm__orient3d (swapping its last two corners when negative) and
 * count the Steiner points: on boundary faces, and the others. CVM_OK,
 * CVM_E_NOMEM, CVM_E_INTERNAL (an index out of range, a flat tetrahedron). */
cvm_status cvm__tet3_finish(cvm__ctx *ctx, cvm__tet3_out *out);

#ifdef __cplusplus
}
#endif

#endif
