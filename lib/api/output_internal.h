/*
 * output_internal.h - the domain of a triangulated mesh in output order,
 * shared by output.c, mesh_out.c and quality.c: triangles are the domain
 * triangles (cvm__tri2_in_domain) in slot order; edges are the unique edges
 * of those triangles sorted by (lower, higher) vertex id.
 */
#ifndef CVM_OUTPUT_INTERNAL_H
#define CVM_OUTPUT_INTERNAL_H

#include "api_internal.h"

/* Unique edges of the domain triangles, sorted by (lo, hi). */
typedef struct cvm__edges {
    int32_t *ev;    /* 2*n vertex ids, ev[2k] < ev[2k+1] */
    int32_t *seg;   /* n: input segment of a constrained edge, or -1 */
    uint8_t *bnd;   /* n: 1 when only one side of the edge is a domain triangle */
    size_t n;
} cvm__edges;

/* Number of domain triangles. */
size_t cvm__domain_triangles(const cvm__tri2 *T);

/* Number of domain triangles of m: 0 when it is not triangulated. */
size_t cvm__mesh_n_triangles(const cvm_mesh *m);

/* Whether an output buffer dst of dst_len entries holds need entries:
 * CVM_E_NULL_ARG when dst is NULL with dst_len > 0, CVM_E_BUFFER_TOO_SMALL when
 * dst_len < need, else CVM_OK (no message set). */
cvm_status cvm__room(const void *dst, size_t dst_len, size_t need);

/* Count the unique edges of the domain triangles (*nedge) and, among them,
 * the constrained ones (*nseg), without allocating. */
void cvm__domain_edge_counts(const cvm__tri2 *T, size_t *nedge, size_t *nseg);

/* Slot -> output triangle index, or -1 for slots outside the domain: T->nt
 * entries allocated through ctx. CVM_OK or CVM_E_NOMEM (no message). */
cvm_status cvm__domain_map(cvm__ctx *ctx, const cvm__tri2 *T, int32_t **map_out);

/* Gather the unique edges (only the constrained ones when constrained_only),
 * sorted. CVM_OK or CVM_E_NOMEM (no message); free with cvm__edges_free(). */
cvm_status cvm__domain_edges(cvm__ctx *ctx, const cvm__tri2 *T, int constrained_only,
                             cvm__edges *out);
void cvm__edges_free(cvm__ctx *ctx, cvm__edges *e);

/* Ends of the dual edge of every edge of e (from cvm__domain_edges with
 * constrained_only = 0), 4 doubles per edge into ends: the power vertices of
 * its two triangles (the first in slot order first), or for a boundary edge
 * the power vertex of its triangle and the edge's power-bisector foot.
 * Constructions: plain doubles. CVM_OK or CVM_E_NOMEM (no message). */
cvm_status cvm__dual_edge_ends(cvm__ctx *ctx, const cvm__tri2 *T, const cvm__edges *e, double *ends);

/* The dual cell polygons of every vertex of T (lib/api/dual_cells.c): off
 * (nv + 1 entries) receives the CSR offsets; xy, when not NULL, receives 2
 * doubles per corner (2 * off[nv]). CVM_OK, CVM_E_NOMEM or CVM_E_TOO_LARGE
 * (no message). */
cvm_status cvm__dual_cells(cvm__ctx *ctx, const cvm__tri2 *T, int32_t *off, double *xy);

/* Writes of the files of path into a write set (the staged one or a fresh one). */
typedef cvm_status (*cvm__mesh_write_fn)(cvm_mesh *m, const char *path, cvm__write_set *ws);

/* A cvm_mesh_write*() call: CVM_E_NULL_ARG without m; else CVM__BEGIN(m), write(m, path)
 * into a fresh write set, then commit it, or discard it when write fails. Returns the
 * first failing status. */
cvm_status cvm__mesh_write_now(cvm_mesh *m, const char *path, cvm__mesh_write_fn write);

/* The end of a cvm_mesh_stage_write*() call that returns s: on an error or
 * cancellation every staged write of m is discarded. Returns s. */
cvm_status cvm__mesh_stage_settle(cvm_mesh *m, cvm_status s);

/* A view of T for dimensionless dual measures (lib/api/dual_quality.c): when
 * the coordinates of T reach beyond 2^300 or all lie below 2^-300 (the
 * constructions of the dual form cubes of coordinate differences, which
 * would overflow or underflow), *view is a shallow copy of T whose
 * coordinates are scaled by 2^-*k and weights by 2^-2*k, in fresh arrays;
 * otherwise *view = *T and *k = 0. A power-of-two scale is exact (up to
 * subnormal parts) and leaves every ratio unchanged. Read-only; release with
 * cvm__scaled_view_free(). CVM_OK or CVM_E_NOMEM (no message). */
cvm_status cvm__scaled_view(cvm__ctx *ctx, const cvm__tri2 *T, cvm__tri2 *view, int *k);
void cvm__scaled_view_free(cvm__ctx *ctx, const cvm__tri2 *T, cvm__tri2 *view);


#endif
