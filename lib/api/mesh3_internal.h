/*
 * mesh3_internal.h - the state behind m->m3, shared by lib/api/mesh3*.c.
 */
#ifndef CVM_API_MESH3_INTERNAL_H
#define CVM_API_MESH3_INTERNAL_H

#include "api/mesh3.h"
#include "common/surf3.h"
#include "delaunay3/delaunay3_internal.h"

/* CVM_REPORT_GEN3_* (740-748, 757-759, 761-764) and CVM_REPORT_DUAL3_* (750-756, 760),
 * at which - 740 */
#define CVM__GEN3_NREPORT 25

struct cvm__mesh3 {
    cvm__surf3 in;           /* the input: points, and facets when a surface was read */
    /* output (valid when have) */
    int have;
    int delaunay;            /* 1: tets are the Delaunay (regular with w) tetrahedralisation of xyz */
    double *xyz;             /* 3*nv vertices: input points less duplicates, then Steiner points */
    size_t nv;
    int32_t *tet;            /* 4*ntet, positively oriented */
    size_t ntet;
    double *tattr;           /* ntet or NULL */
    int32_t *face;           /* 3*nface: boundary faces (and internal facets of a recovered mesh) */
    int32_t *fmark;          /* nface or NULL */
    size_t nface;
    int32_t *input_map;      /* in.np: input point -> vertex */
    double *w;               /* nv weights (regular), or NULL */
    size_t n_dup, n_redundant, n_steiner_boundary, n_steiner_interior;
    double gen3[CVM__GEN3_NREPORT]; /* report of the last cvm_mesh_generate3() and
                                       cvm_mesh_optimise_dual3(): value
                                       CVM_REPORT_GEN3_MATCHED_PAIRS + k at k */
};

/* Face adjacency of a tetrahedron list: nbr[4 t + f] = 4 u + g when face f of
 * t (opposite corner f) is face g of u, -1 on the boundary; CVM_E_INPUT_DEGENERATE
 * (with a message) when a face is shared by three or more tetrahedra. */
cvm_status cvm__mesh3_adjacency(cvm__ctx *ctx, const int32_t *tet, size_t ntet, int32_t **nbr_out);
/* The faces of a tetrahedron list, sorted by their corners, for lookups. */
typedef struct cvm__face_key {
    int32_t v[3]; /* sorted corners */
    int32_t slot; /* 4 t + f */
} cvm__face_key;
cvm_status cvm__mesh3_face_index(cvm__ctx *ctx, const int32_t *tet, size_t ntet,
                                 cvm__face_key **out);
/* A slot 4 t + f whose face has the corners a, b, c (any order), or -1. */
int32_t cvm__mesh3_find_face(const cvm__face_key *index, size_t n, int32_t a, int32_t b, int32_t c);
/* The corners of face f of tet t, oriented outwards (seen from outside
 * counter-clockwise): for f = 0..3. */
void cvm__mesh3_face_corners(const int32_t *t, int f, int32_t out[3]);
/* 1 when the oriented faces f (of one tetrahedron) and o (of its neighbour, both from
 * cvm__mesh3_face_corners()) are the same triangle seen from opposite sides. */
int cvm__mesh3_faces_opposite(const int32_t *f, const int32_t *o);
/* cf[4 t + f] = 1 for the faces with no neighbour (nbr, from cvm__mesh3_adjacency) and
 * the faces in g->face (the surface and its internal facets), else 0 (mesh3_faces.c).
 * CVM_OK or CVM_E_NOMEM (message set). */
cvm_status cvm__mesh3_constrained_faces(cvm__ctx *ctx, const cvm__mesh3 *g, const int32_t *nbr,
                                        uint8_t **out);
/* Without hole or region points in g->in: remove the tetrahedra on the side the input
 * triangles tri (3*nt input point ids, as oriented in the input) face, and every tetrahedron
 * reached from them without crossing a triangle, then the vertices left unused (mesh3_shells.c).
 * Nothing changes when the orientation contradicts itself (a tetrahedron both in front of and
 * behind the surface: internal facets) or would remove everything. *removed: tetrahedra
 * removed. CVM_OK or CVM_E_NOMEM (the mesh is then unchanged). */
cvm_status cvm__mesh3_carve_by_orientation(cvm__ctx *ctx, cvm__mesh3 *g, const int32_t *tri,
                                           size_t nt, size_t *removed);

/* A tetrahedral mesh given by the caller (mesh3_tets.c): the nt tetrahedra tets (4 point
 * ids each, 0-based) on the np points xyz, with attributes attr (or NULL), checked and
 * built into out's output fields (vertices = the points in order, tetrahedra positively
 * oriented, boundary and attribute-interface faces in out->face, have 1). Messages
 * number tetrahedra from tbase and points from pbase (the file's numbering). Statuses:
 * CVM_E_INPUT_EMPTY, CVM_E_TOO_LARGE, CVM_E_INPUT_INDEX, CVM_E_INPUT_DEGENERATE (a
 * repeated or unused point, a flat tetrahedron, a face of three tetrahedra),
 * CVM_E_INPUT_NONFINITE (an attribute), CVM_E_INPUT_INTERSECTING (two tetrahedra on one
 * side of a shared face; a boundary that intersects itself or is not manifold),
 * CVM_E_INPUT_NOT_CLOSED, CVM_E_NOMEM; out is empty on error. */
cvm_status cvm__mesh3_tets_build(cvm__ctx *ctx, const double *xyz, size_t np, const int32_t *tets,
                                 const double *attr, size_t nt, long long tbase, long long pbase,
                                 cvm__mesh3 *out);
void cvm__mesh3_tets_free(cvm__ctx *ctx, cvm__mesh3 *out);
/* Replace m's mesh by the one built in b (mesh3.c); b is emptied. */
void cvm__mesh3_take_tets(cvm_mesh *m, cvm__mesh3 *b);

#endif
