/*
 * boundary_internal.h - the boundary engine: re-discretising the input
 * boundary before refinement (CVM_OPT_KEEP_SEGMENT_VERTICES = 0). Chains of
 * constrained edges that form a smooth curve are resampled as one curve with
 * the sizing and the constrained triangulation is rebuilt from the result.
 *
 * The engine works on a cvm__tri2 and plain arrays; it never sees the
 * cvm_mesh handle. Whether a chord may replace an arc is decided with the
 * exact orientation test; where the new points go (the sizing integral) is
 * floating point and only chooses which valid boundary results.
 */
#ifndef CVM_BOUNDARY_INTERNAL_H
#define CVM_BOUNDARY_INTERNAL_H

#include <stddef.h>
#include <stdint.h>
#include "common/common_internal.h"
#include "delaunay/delaunay_internal.h"
#include "sizing/sizing_internal.h"

/* What the resampler reads (all borrowed). */
typedef struct cvm__resample_input {
    const cvm__tri2 *T;        /* carved, constrained, unweighted (as cvm_mesh_triangulate() left it) */
    const cvm_sizing *sizing;  /* not empty */
    const int32_t *smark;      /* input segment markers as for cvm__cdt_segment_marker() */
    size_t nseg;
    const double *holes;       /* 2 per hole: no chord may swallow one */
    size_t nholes;
    const double *regions;     /* 4 per region (x, y, ...): no chord may swallow a seed */
    size_t nregions;
    uint64_t seed;             /* point-order seed of the rebuilt triangulation */
    int keep_hull;             /* CVM_OPT_KEEP_CONVEX_HULL: hull edges are kept, never resampled */
} cvm__resample_input;

/* What it produces when n_chains > 0 (else everything is empty). */
typedef struct cvm__resample_result {
    size_t n_chains;           /* chains re-discretised; 0: keep the input as it is */
    cvm__tri2 T;               /* the rebuilt constrained triangulation, not carved */
    int32_t *newid;            /* per vertex of the input T: its id in T, or -1 (removed) */
    size_t nkept;              /* kept vertices are 0..nkept-1 of T; new point k is nkept + k */
    size_t nnew;
    int32_t *ninfo;            /* 3 per new point: its segment id, then the ends (input T ids)
                                  of the input edge it lies on */
    double *nfrac;             /* per new point: its position on that edge, 0 at the first end */
} cvm__resample_result;

/* Re-discretise the smooth chains of in->T with in->sizing and rebuild the
 * triangulation into R (see cvm__resample_input). R->n_chains = 0 when no
 * chain could be re-discretised or the result would not make a valid
 * constrained triangulation. CVM_OK, CVM_E_NOMEM, the sizing's errors (with
 * their message on ctx) or CVM_INCOMPLETE_* from the rebuild; R is to be
 * released with cvm__resample_result_free() on every return. */
cvm_status cvm__resample_boundary(cvm__resample_result *R, const cvm__resample_input *in,
                                  cvm__ctx *ctx);
void cvm__resample_result_free(cvm__resample_result *R, cvm__ctx *ctx);

#endif
