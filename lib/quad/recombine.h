/*
 * recombine.h - Blossom-Quad recombination of a triangulation into a
 * quad-dominant mesh (Remacle et al. 2012, "Blossom-Quad: a non-uniform
 * quadrilateral mesh generator using a minimum-cost perfect-matching
 * algorithm"), with quad quality measured in the space of a Riemannian
 * metric (issue 19).
 *
 * Graph nodes are triangles, graph edges the interior unconstrained edges; an
 * edge weighs the quality of the quad its two triangles form,
 *   q = 1 - max over the 4 corners of |theta - 90 deg| / 90 deg,
 * with the corner angles theta measured in the metric g at the quad's
 * centroid (g constant over the quad: the angle between corner edges u, v is
 * acos(u'gv / sqrt(u'gu v'gv))). A quad that is not strictly convex (exact
 * orientation tests) has q = 0 and is never formed; pairs with q below the
 * threshold are not candidates. The weights go to the matching solver as
 * cvm__match_scale(q) (q rounded to multiples of 2^-20).
 */
#ifndef CVM_QUAD_RECOMBINE_H
#define CVM_QUAD_RECOMBINE_H

#include <stddef.h>
#include <stdint.h>
#include "common/common_internal.h"

/* Metric at (x, y): g = (g11, g12, g22), symmetric positive definite. Returns 0
 * on success; non-zero rejects the point (reported as CVM_E_ARGUMENT). */
typedef int (*cvm__metric_fn)(double x, double y, double g[3], void *user);

typedef enum cvm__recombine_method {
    CVM__RECOMBINE_BLOSSOM = 0, /* maximum-weight matching (matching.h) */
    CVM__RECOMBINE_GREEDY = 1   /* greedy matching by decreasing quality, for comparison */
} cvm__recombine_method;

typedef struct cvm__recombine_in {
    size_t npts;
    const double *xy;                /* 2 * npts coordinates */
    size_t ntri;
    const cvm_index *tri;            /* 3 * ntri point ids, counter-clockwise */
    const unsigned char *side_fixed; /* NULL, or 3 * ntri flags: side j of triangle t, from
                                        tri[3t+j] to tri[3t+(j+1)%3], is constrained (a segment)
                                        when non-zero; an edge is fixed if either side says so.
                                        Boundary edges (one triangle) are never paired. */
    const double *g;                 /* NULL, or 3 * npts metric tensors (g11, g12, g22): a
                                        quad's metric is the mean of its 4 corners' tensors */
    cvm__metric_fn metric;           /* used when g is NULL: the metric at the quad centroid; */
    void *metric_user;               /* both NULL: the identity (Euclidean angles) */
    double min_quality;              /* pairs with q below are left as triangles; in [0, 1],
                                        the default is 0.5 */
    cvm__recombine_method method;
    int perfect;                     /* blossom only: maximum number of quads first, then
                                        maximum quality (CVM__MATCH_MAX_CARDINALITY) */
    int all_quad;                    /* split every cell of the result: a quad into 4, a
                                        triangle into 3 quads, through its vertex centroid and
                                        its edge midpoints (shared between neighbours) */
} cvm__recombine_in;

/* Mixed cells in the layout of cvm_mesh_copy_cells_mixed(): cell c has type
 * types[c] (CVM_CELL_QUAD = 9 or CVM_CELL_TRIANGLE = 5, VTK codes) and the
 * counter-clockwise point ids conn[offsets[c] .. offsets[c+1]-1]. Cells come
 * in the order of their lowest input triangle. With all_quad, every cell is
 * a quad and the ids refer to xy: the input points, then one midpoint per
 * edge, then one centroid per quad-dominant cell (constructed in doubles);
 * a sub-quad's quality uses its parent cell's metric and is 0 when it is not
 * strictly convex. nquad and ntri count the quad-dominant cells before the
 * split. */
typedef struct cvm__recombine_out {
    size_t ncell, nquad, ntri;
    cvm_index *offsets;   /* ncell + 1 */
    int32_t *types;       /* ncell */
    cvm_index *conn;      /* 4 nquad + 3 ntri */
    cvm_index *source;    /* 2 per cell: the input triangles (-1 second for a triangle) */
    double *quality;      /* per cell: q of a quad, 0 for a triangle */
    double total_quality; /* sum of q over the quads */
    size_t npts;          /* all_quad: number of points of xy; else 0 */
    double *xy;           /* all_quad: 2 * npts coordinates; else NULL */
} cvm__recombine_out;

/*
 * Recombine in into out (arrays allocated through ctx; free with
 * cvm__recombine_out_free(); out is zeroed on error).
 * Returns CVM_OK; CVM_E_NULL_ARG; CVM_E_INPUT_INDEX (a triangle names a point
 * outside [0, npts), message gives it); CVM_E_INPUT_NONFINITE (a coordinate);
 * CVM_E_INPUT_DEGENERATE (a triangle not strictly counter-clockwise, or an
 * edge shared by more than two triangles or by two of one orientation: the
 * message names them); CVM_E_ARGUMENT (a metric that is not finite and SPD,
 * or that the callback rejects: message gives the point; min_quality outside
 * [0, 1]; an unknown method); CVM_E_TOO_LARGE; CVM_E_NOMEM.
 * Deterministic. Thread-safety: reentrant (the callback must be too).
 */
cvm_status cvm__recombine(cvm__recombine_out *out, cvm__ctx *ctx, const cvm__recombine_in *in);

void cvm__recombine_out_free(cvm__ctx *ctx, cvm__recombine_out *out);

#endif
