/*
 * quadmesh_internal.h - shared between quadmesh.c and quadmesh_sites.c.
 */
#ifndef CVM_QUADMESH_INTERNAL_H
#define CVM_QUADMESH_INTERNAL_H

#include "api_internal.h"
#include "quad/quad_internal.h"

/* The metric of mt as a cvm__metric_fn-style callback (user: a cvm__qm_metric_cb): nonzero when
 * the checked evaluation fails (its message on ctx). */
typedef struct cvm__qm_metric_cb {
    const cvm__metric *mt;
    cvm__ctx *ctx;
} cvm__qm_metric_cb;
int cvm__qm_metric_at(double x, double y, double g[3], void *user);

/* The sites as the triangulation of m: the input points (so they keep their vertex numbers),
 * the new boundary points of bxy (the loop's nc vertices, with the input segments lseg of its
 * edges, are its corners, met in order), then the interior sites xi that lie strictly inside,
 * in order; segments along bxy with the markers of the loop's input segments. Drops m's
 * output first (the quad cells with it). *kept_out: the interior sites kept. CVM_OK,
 * CVM_E_NOMEM, CVM_E_UNSUPPORTED (a corner that is not an input point), CVM_E_INTERNAL. */
cvm_status cvm__qm_triangulate_sites(cvm_mesh *m, const int32_t *loop, const int32_t *lseg,
                                     size_t nc, const double *bxy, size_t nb, const double *xi,
                                     size_t ni, size_t *kept_out);

/* CVM_OPT_QUAD_SMOOTH: smooth the interior sites of m's cells (cvm__quad_smooth(), quality
 * rewritten), then triangulate the sites again; the cells keep their vertex numbers. Skipped
 * (CVM_OK) when the interior sites are not the last kept vertices in xi's order (a site merged
 * with another). The arguments are those of the triangulation that made the cells. */
cvm_status cvm__qm_smooth_cells(cvm_mesh *m, const cvm__metric *mt, const int32_t *loop,
                                const int32_t *lseg, size_t nc, const double *bxy, size_t nb,
                                const double *xi, size_t ni, size_t kept);

/* CVM_OPT_QUAD_ALL_QUAD: m's cells refer to the points pxy (np: m's vertices, then the split's
 * new points). The boundary sites bxy (nb) get their edges' midpoints (exactly as the split
 * rounds them: *bxy_out, 2 nb, on m's ctx); the interior sites become m's kept_in interior
 * vertices then the split's other new points (*xi_out, *ni_out); m is triangulated again with
 * them (*kept_out) and the cells renumbered to its vertices (matched by exact coordinates).
 * CVM_OK, CVM_E_NOMEM, the triangulation's errors, CVM_E_INTERNAL (a point not found). */
cvm_status cvm__qm_adopt_split(cvm_mesh *m, const int32_t *loop, const int32_t *lseg, size_t nc,
                               const double *bxy, size_t nb, size_t kept_in, const double *pxy,
                               size_t np, double **bxy_out, size_t *nb_out, double **xi_out,
                               size_t *ni_out, size_t *kept_out);

#endif
