/*
 * mesh_oracle.h - an independent checker of triangle meshes for the tests.
 *
 * It re-derives, with its own code and only the exact predicates of lib/geom,
 * what a correct mesh must satisfy: every triangle strictly counter-clockwise,
 * every edge in at most two triangles with opposite directions, every interior
 * vertex wound exactly once, every constrained edge a mesh edge, every input
 * segment a union of mesh edges (walking collinear chains), every interior
 * non-constrained edge locally Delaunay (exact incircle), and optionally the
 * Euler characteristic, the total area, and convex-hull coverage.
 * It shares no code with cvm_mesh_check(), so a bug must fool both.
 */
#ifndef CVMTEST_MESH_ORACLE_H
#define CVMTEST_MESH_ORACLE_H

#include <stddef.h>
#include "cvmesh.h"

typedef struct cvmtest_expect {
    int delaunay;          /* 1: interior non-constrained edges locally Delaunay (default 1) */
    int check_euler;       /* 1: V - E + F (used vertices) must equal euler */
    long euler;            /* components - holes of the domain, e.g. 1 for a disc, 0 for an annulus */
    int check_area;        /* 1: total area must equal area within area_rel_tol */
    double area;
    double area_rel_tol;   /* relative tolerance of the area (floating-point sum); default 1e-12 */
    int convex;            /* 1: the domain is the convex hull of all vertices and every vertex is
                              used (Delaunay of a point set); -1: decide from the handle (default) */
    const cvm_index *segs; /* input segments: 2*nseg INPUT point ids (mapped through the input map),
                              or NULL */
    size_t nseg;
} cvmtest_expect;

/* Defaults: delaunay 1, convex -1, nothing else checked. */
void cvmtest_expect_init(cvmtest_expect *e);

/*
 * Check a mesh given as arrays. xy: 2*nv coordinates; tri: 3*nt vertex ids;
 * cons: 2*ncons constrained edges (exempt from the Delaunay test; each must be
 * a mesh edge), may be NULL; input_map: n_input entries mapping input point ids
 * to vertex ids (NULL: identity). Vertices of id >= 1 + max(input_map) are
 * Steiner points, which may lie off the segment they split (rounded
 * intersections). e may be NULL (defaults; convex -1 counts as 0 here).
 * Returns 1 if valid, else 0 with a message in msg naming the failed check.
 */
int cvmtest_oracle(char *msg, size_t msglen, const double *xy, size_t nv, const cvm_index *tri,
                   size_t nt, const cvm_index *cons, size_t ncons, const cvm_index *input_map,
                   size_t n_input, const cvmtest_expect *e);

/*
 * Fetch points, triangles, output segments and the input map of m through the
 * public API and run cvmtest_oracle(). With e->convex == -1 the convex check is
 * on when m has neither input segments nor holes. Returns 1 if valid.
 */
int cvmtest_mesh_validate(char *msg, size_t msglen, cvm_mesh *m, const cvmtest_expect *e);

/*
 * Smallest angle of triangle (a, b, c) in degrees, each corner by atan2 of the
 * cross and dot products of its edges. The tests' own measure, written apart
 * from the library's (lib/geom/measure.c) on purpose: a check of the angles the
 * library reports must not reuse the code it checks.
 */
double cvmtest_tri_min_angle_deg(const double *a, const double *b, const double *c);

#ifndef CVMTEST_NO_CHECK
/* Check assertions: cvm_mesh_check(m) == CVM_OK and the oracle with defaults (or e). */
void cvmtest_assert_valid(cvm_mesh *m);
void cvmtest_assert_valid_ex(cvm_mesh *m, const cvmtest_expect *e);
#endif

#endif
