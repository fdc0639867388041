/* g3_util.h - the generated 3D mesh as plain arrays, and the combinatorial
 * facts the generate3 tests check on it (tests/unit/generate3). */
#ifndef CVMTEST_G3_UTIL_H
#define CVMTEST_G3_UTIL_H

#include <check.h>
#include <stddef.h>
#include <stdint.h>
#include "cvmesh.h"

typedef struct g3_mesh {
    size_t nv, nt, nf;
    double *xyz;       /* 3 nv */
    cvm_index *tet;    /* 4 nt */
    cvm_index *face;   /* 3 nf: CVM_ENT_TRIANGLE */
    int64_t *edge;     /* ne unique edges a * nv + b, a < b */
    size_t ne;
    int64_t *tface;    /* unique faces of the tetrahedra */
    size_t ntf;
    size_t nbnd;       /* faces of one tetrahedron only */
    int32_t *valence;  /* nv */
} g3_mesh;

/* Copy m's mesh and count its edges, faces and valences. */
void g3_mesh_get(g3_mesh *g, const cvm_mesh *m);
void g3_mesh_free(g3_mesh *g);
/* V - E + F - T. */
int64_t g3_euler(const g3_mesh *g);
/* The face a, b, c (any order) as the key of tface. */
int64_t g3_face_key(const g3_mesh *g, cvm_index a, cvm_index b, cvm_index c);
/* 1 when the face appears exactly once among the tetrahedra's faces. */
int g3_face_on_boundary(const g3_mesh *g, cvm_index a, cvm_index b, cvm_index c);
/* The path of a 3D example surface: $CVM_DATA3D_DIR/name, else examples/data3d/name. */
void g3_data3d(char *buf, size_t len, const char *name);
/* 1 when this build recovers boundaries with TetGen. */
int g3_with_tetgen(void);
/* The sum of the tetrahedra's volumes. */
double g3_tet_volume(const g3_mesh *g);
/* Asserts that the boundary faces as directed edges hold each edge once and
 * its reverse once (closed and consistently oriented). */
void g3_assert_closed_oriented(const g3_mesh *g);

#endif
