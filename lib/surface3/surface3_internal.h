/*
 * surface3_internal.h - validation of a 3D boundary surface (a cvm__surf3)
 * before it is tetrahedralised: every face is a proper polygon, the surface
 * is closed, manifold and consistently oriented, and no two faces intersect
 * other than in their shared corners and edges. Every decision is taken by
 * the exact predicates of lib/geom (orient3d, and orient2d on the coordinate
 * projections), so the verdict is the same on every machine.
 *
 * Thread-safety: pure functions of their arguments; allocation through ctx.
 */
#ifndef CVM_SURFACE3_INTERNAL_H
#define CVM_SURFACE3_INTERNAL_H

#include <stddef.h>
#include <stdint.h>
#include "common/surf3.h"

/* The triangles of a surface: polygons with more than 3 corners fanned. */
typedef struct cvm__surf3_tris {
    int32_t *tri;      /* 3*nt point indices, in the orientation of their polygon */
    int32_t *tpoly;    /* nt: the polygon of each triangle */
    size_t nt;
    size_t nshell;     /* connected components (through shared edges) */
} cvm__surf3_tris;

void cvm__surf3_tris_free(cvm__ctx *ctx, cvm__surf3_tris *t);

/* Accept edges shared by 3 or more faces, which internal facets between two
 * regions make (e.g. two cubes sharing a face). Orientation is then checked
 * at the 2-face edges only, and a vertex is manifold when its faces are
 * connected through any shared edges. */
#define CVM__SURF3_ALLOW_INTERNAL 1

/* Split the polygons of s into triangles, checking each polygon:
 * CVM_E_INPUT_DEGENERATE  a corner repeats, a triangle's corners are
 *                         collinear, a polygon is not planar
 * CVM_E_UNSUPPORTED       a polygon of 1 or 2 corners, a facet with holes,
 *                         a planar polygon that is not strictly convex
 * CVM_E_NOMEM. Messages name the face in the file's numbering. */
cvm_status cvm__surf3_triangulate(cvm__ctx *ctx, const cvm__surf3 *s, cvm__surf3_tris *out);

/* The edges of t: closed, consistently oriented and manifold.
 * CVM_E_INPUT_NOT_CLOSED   an edge of one face only (open surface), or two
 *                          faces whose shared edge runs the same way (one is
 *                          flipped)
 * CVM_E_INPUT_INTERSECTING an edge of 3 or more faces (without
 *                          CVM__SURF3_ALLOW_INTERNAL), a vertex where
 *                          separate fans of faces meet (non-manifold vertex),
 *                          two faces with the same corners
 * CVM_E_NOMEM. Sets t->nshell. */
cvm_status cvm__surf3_check_topology(cvm__ctx *ctx, const cvm__surf3 *s, cvm__surf3_tris *t, int flags);

/* No two triangles of t meet except in the corners and edges they share
 * (exact tests; a uniform grid keeps the pairs tested near linear).
 * CVM_E_INPUT_INTERSECTING (names both faces), CVM_E_NOMEM. */
cvm_status cvm__surf3_check_intersections(cvm__ctx *ctx, const cvm__surf3 *s, const cvm__surf3_tris *t);

/* All of the above in order; out receives the triangles (freed on error). */
cvm_status cvm__surf3_validate(cvm__ctx *ctx, const cvm__surf3 *s, int flags, cvm__surf3_tris *out);

/* ---- exact tests on triangles (tri_intersect.c) ---- */

/* 1 when the closed triangles abc and def (each non-degenerate) meet in more
 * than the corners they share by index: ia..if are their point indices, so
 * shared corners are recognised by index, not by coordinates. */
int cvm__tri_tri_improper(const double *a, const double *b, const double *c, const double *d,
                          const double *e, const double *f, const int32_t *iabc, const int32_t *idef);
/* 1 when a, b, c are collinear (exactly: all three coordinate projections). */
int cvm__collinear3(const double *a, const double *b, const double *c);

/* "face 12 (points 4, 9, 11)" for polygon poly of s, in the file's numbering. */
void cvm__surf3_name_poly(const cvm__surf3 *s, size_t poly, char *buf, size_t cap);

#endif
