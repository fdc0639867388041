/*
 * mesh3_dual.h - the power (Voronoi without weights) dual of a 3D handle's
 * tetrahedralisation (lib/api/mesh3_dual.c): a dual vertex per tetrahedron
 * (its power vertex; tetrahedra whose power vertices coincide exactly, by the
 * exact power test across their shared face, share one), a dual face per
 * interior edge (the polygon of the power vertices of the tetrahedra around
 * it), a dual edge per interior face, and a bounded cell per interior vertex.
 */
#ifndef CVM_API_MESH3_DUAL_H
#define CVM_API_MESH3_DUAL_H

#include "api/mesh3_internal.h"

typedef struct cvm__dual3 {
    size_t nv, ntet;
    double *pv;           /* 3 * ntet: power vertex of each tetrahedron */
    int32_t *dvert;       /* ntet: dual vertex of each tetrahedron (0 .. ndv - 1, first tet order) */
    int32_t *dv_tet;      /* ndv: the first tetrahedron of each dual vertex */
    size_t ndv;
    int32_t *nbr;         /* 4 * ntet: face adjacency (cvm__mesh3_adjacency) */
    unsigned char *vbnd;  /* nv: 1 for a vertex on a boundary face or in no tetrahedron */
    int32_t *edge;        /* 2 * nedge: the edges (a < b), sorted */
    int32_t *edge_tet;    /* nedge: a tetrahedron of the edge */
    double *edge_area;    /* nedge: signed dual face area, oriented along b - a; 0 on the boundary */
    unsigned char *edge_in; /* nedge: 1 when interior (its ring of tetrahedra closes) */
    size_t nedge;
    int32_t *vedge_off;   /* nv + 1: CSR of the edges at each vertex */
    int32_t *vedge;
    double *volume;       /* nv: dual cell volume of an interior vertex, -1 on the boundary */
    int32_t *ring;        /* scratch for cvm__dual3_ring */
    size_t ring_cap;
} cvm__dual3;

/* Build the dual of g's tetrahedra (g->have); CVM_E_NOMEM (message set) or
 * CVM_E_TOO_LARGE. d is zeroed first and freed on error. */
cvm_status cvm__dual3_build(cvm__ctx *ctx, const cvm__mesh3 *g, cvm__dual3 *d);
void cvm__dual3_free(cvm__ctx *ctx, cvm__dual3 *d);
/* The tetrahedra around edge e in positive rotation about edge[2e+1] -
 * edge[2e] into d->ring (grown as needed); the count, or 0 for a boundary
 * edge (open ring), or -1 when out of memory (message set). */
long cvm__dual3_ring(cvm__ctx *ctx, cvm__dual3 *d, const int32_t *tet, size_t e);
/* The dual face of interior edge e as dual vertex ids without cyclic repeats
 * (ties merged), oriented along edge[2e+1] - edge[2e], into d->ring; its
 * length (< 3: the face vanished, or a boundary edge), or -1 (out of memory). */
long cvm__dual3_face(cvm__ctx *ctx, cvm__dual3 *d, const int32_t *tet, size_t e);

#endif
