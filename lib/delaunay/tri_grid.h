/* tri_grid.h - the point-location grid of a set of triangles given as
 * point indices (a mesh file's cells; tri_grid.c). */
#ifndef CVM_DELAUNAY_TRI_GRID_H
#define CVM_DELAUNAY_TRI_GRID_H

#include "delaunay_internal.h"

/* Triangles tri[3k..3k+2] (indices into xy, 2 per point) bucketed by a
 * uniform grid over the points, each listed in every cell its bounding box
 * meets, so a point is tested against the triangles of its own cell only:
 * the cell of a coordinate is a monotone function of it, so a triangle
 * containing p always meets p's cell. */
typedef struct cvm__tri_grid {
    const double *xy;      /* borrowed: the points and triangles */
    size_t np;
    const int32_t *tri;
    size_t nt;
    double x0, y0, sx, sy; /* lower corner, cells per unit length */
    size_t side, n;        /* cells per axis, listings */
    size_t *start;         /* side^2 + 1: cell c lists idx[start[c]..start[c+1]) */
    int32_t *idx;
} cvm__tri_grid;

/* Bucket the triangles (xy, tri are borrowed until cvm__tri_grid_free).
 * CVM_OK or CVM_E_NOMEM (no message). */
cvm_status cvm__tri_grid_build(cvm__ctx *ctx, cvm__tri_grid *g, const double *xy, size_t np,
                                const int32_t *tri, size_t nt);
void cvm__tri_grid_free(cvm__ctx *ctx, cvm__tri_grid *g);
/* 1 when p lies in (or on) one of the triangles, in either orientation
 * (exact orientation tests). */
int cvm__tri_grid_contains(const cvm__tri_grid *g, const double *p);

#endif
