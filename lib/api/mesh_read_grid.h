/* mesh_read_grid.h - the point-location grid of a mesh file's triangles (mesh_read_grid.c). */
#ifndef CVM_API_MESH_READ_GRID_H
#define CVM_API_MESH_READ_GRID_H

#include "api_internal.h"

/* The file's triangles bucketed by a uniform grid over the points, each
 * listed in every cell its bounding box meets, so a point is tested against
 * the triangles of its own cell only: the cell of a coordinate is a
 * monotone function of it, so a triangle containing p always meets p's cell. */
typedef struct cvm__file_grid {
    double x0, y0, sx, sy; /* lower corner, cells per unit length */
    size_t side, n;        /* cells per axis, listings */
    size_t *start;         /* side^2 + 1: cell c lists idx[start[c]..start[c+1]) */
    int32_t *idx;
} cvm__file_grid;

/* Bucket the file's triangles. CVM_OK or CVM_E_NOMEM (no message). */
cvm_status cvm__file_grid_build(cvm__ctx *ctx, const cvm__vtu_mesh *vm, cvm__file_grid *g);
void cvm__file_grid_free(cvm__ctx *ctx, cvm__file_grid *g);
/* 1 when p lies in (or on) a triangle of the file (exact orientation tests). */
int cvm__file_grid_in_domain(const cvm__vtu_mesh *vm, const cvm__file_grid *g, const double *p);

#endif
