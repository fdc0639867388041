/* domain.h - the domain of a triangulation in output order (domain.c): triangles are the domain
 * triangles (cvm__tri2_in_domain) in slot order; edges are the unique edges of those triangles
 * sorted by (lower, higher) vertex id. */
#ifndef CVM_DELAUNAY_DOMAIN_H
#define CVM_DELAUNAY_DOMAIN_H

#include "delaunay_internal.h"

/* Unique edges of the domain triangles, sorted by (lo, hi). */
typedef struct cvm__edges {
    int32_t *ev;    /* 2*n vertex ids, ev[2k] < ev[2k+1] */
    int32_t *seg;   /* n: input segment of a constrained edge, or -1 */
    uint8_t *bnd;   /* n: 1 when only one side of the edge is a domain triangle */
    size_t n;
} cvm__edges;

/* Number of domain triangles. */
size_t cvm__domain_triangles(const cvm__tri2 *T);

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

/* ---- measures of the domain triangles (domain_quality.c) ---- */

#define CVM__NBIN_ANGLE 18  /* CVM_HIST_ANGLE_DEG */
#define CVM__NBIN_DEGREE 16 /* CVM_HIST_DEGREE */

/* Angles, edges and area of the domain triangles. */
typedef struct cvm__tri_quality {
    size_t nt;
    double min_angle, max_angle;   /* degrees */
    size_t n_regular, n_obtuse;    /* angles in [55, 65] degrees; triangles with a dot < 0 */
    double min_edge, max_edge;     /* lengths */
    double area, area_c, min_area; /* Neumaier sum and its compensation */
    double angle_hist[CVM__NBIN_ANGLE]; /* 10-degree bins, the last one open */
} cvm__tri_quality;

/* The measures of the domain triangles of T into q (a domain without
 * triangles gives nt 0 and the extremes +-HUGE_VAL/0). */
void cvm__domain_triangle_stats(const cvm__tri2 *T, cvm__tri_quality *q);
/* Degrees of the interior vertices of the domain of T: hist
 * (CVM__NBIN_DEGREE bins, by degree, the last one open) and *n_interior.
 * CVM_OK or CVM_E_NOMEM (no message). */
cvm_status cvm__domain_degree_stats(cvm__ctx *ctx, const cvm__tri2 *T, double *hist,
                                    size_t *n_interior);

#endif
