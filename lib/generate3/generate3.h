/*
 * generate3.h - the points of a 3D co-volume mesh inside a closed surface
 * (Walton, Hassan and Morgan's modified advancing front + lattice): a near
 * field of one point per pair of matched surface triangles (or per unmatched
 * triangle) and a body-centred cubic (BCC) lattice in the free space. The
 * points are then tetrahedralised with the surface by the 3D kernel
 * (lib/api/generate3.c); this folder only decides where the points go.
 *
 * Files: g3_sizing.c (the size field), g3_grid.c (range queries), g3_inside.c
 * (exact point-in-domain test), g3_near.c (matching and near-field placement),
 * g3_lattice.c (the free-space lattice), g3_octree.c and g3_refine.c (the
 * other free-space methods), g3_recover.c (dropping generated
 * points that hide a surface triangle from the Delaunay tetrahedralisation),
 * g3_surface.c (planar facets re-meshed in 2D), g3_run.c (the sequence).
 *
 * Size field: with follow_surface, size(x) = min(h, min over surface
 * triangles f of l(f) + g |x - centroid(f)|), l(f) the mean edge length of f;
 * else size(x) = h; and with a user sizing (3D, lib/sizing), the least of
 * that and the sizing at x.
 *
 * Free space, this version: a global axis-aligned BCC lattice (origin at the
 * surface's bounding-box corner), one level per halving of the size (cube
 * edge a_k = h / 2^k; a candidate of level k is kept where a_k/2 < size(x) <=
 * a_k), clipped by the exact inside test and by the distance rule. With a
 * user sizing the levels go down to its sources' least size (with a
 * callback, on while a level meets sizes below its range), and a finer level
 * also visits the boxes where a source can reach its size
 * (cvm__sizing_boxes3). The lattice grown front by front in a local
 * frame is not implemented.
 *
 * Geometry that decides topology (inside or not, which surface triangles are
 * Delaunay faces) is exact; placements, sizes and distances are plain doubles.
 * Deterministic: no threads, every order is the input order. Memory through
 * the context's allocator; CVM_E_NOMEM leaves nothing allocated.
 */
#ifndef CVM_GENERATE3_H
#define CVM_GENERATE3_H

#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include "common/common_internal.h"
#include "sizing/sizing_internal.h"

/* The closed surface: np points, nt triangles oriented with their right-hand
 * normal out of the domain (as lib/surface3 validates them). */
typedef struct cvm__g3_surface {
    const double *xyz;
    size_t np;
    const int32_t *tri;
    size_t nt;
} cvm__g3_surface;

typedef struct cvm__g3_params {
    double h;           /* largest size, > 0 and finite */
    double grading;     /* g of the size field, > 0 */
    int follow_surface; /* 1: size from the surface's triangles; 0: uniform h */
    int layers;         /* near-field layers; only 1 in this version */
    const cvm_sizing *sizing; /* NULL, or a 3D sizing (cvm__sizing_check3 passed) */
    int freespace;      /* CVM_GEN3_FREESPACE_*: lattice, octree or Delaunay refinement */
    int octree_balance; /* 6: 2:1 across faces; 26: across faces, edges and corners */
    int octree_split_hanging; /* 1: leaves with finer face neighbours split once */
    size_t refine_max;  /* refinement: at most this many points inserted (0: no limit) */
    double lattice_dmf; /* the lattice's rejection distance over size (<= 0: 0.55) */
    double near_wall;   /* a near-field point closer than this x delta to a surface triangle
                           is not placed (0: no such test) */
} cvm__g3_params;

typedef struct cvm__g3_report {
    size_t matched_pairs;   /* pairs of surface triangles matched */
    size_t unmatched_faces; /* triangles left alone */
    size_t pairs_rejected;  /* adjacent pairs dropped by the well-centred-region test */
    size_t near_points;     /* near-field points kept */
    size_t near_rejected;   /* near-field points outside the domain or within dm of a node */
    size_t lattice_points;  /* free-space points kept */
    size_t lattice_levels;  /* lattice levels that contributed a point */
    size_t recovery_dropped; /* generated points removed so that every surface triangle is
                                a face of the Delaunay tetrahedralisation */
    size_t octree_leaves;   /* leaves of the balanced octree (free space octree) */
    size_t octree_points;   /* octree centroids kept */
    size_t refine_points;   /* circumcentres inserted (free space refine) */
    size_t refine_rounds;   /* rounds of refinement that had candidates */
    int refine_limited;     /* refinement stopped at the point limit (refine_max) */
    int surface_not_delaunay; /* check_faces: the surface's own points already miss a triangle */
} cvm__g3_report;

/* ---- g3_sizing.c ---- */
typedef struct cvm__g3_size cvm__g3_size;
cvm_status cvm__g3_size_create(cvm__g3_size **out, cvm__ctx *ctx, const cvm__g3_surface *s,
                               const cvm__g3_params *p);
void cvm__g3_size_free(cvm__g3_size *z);
double cvm__g3_size_eval(const cvm__g3_size *z, const double *x);
/* The size at x with the user sizing, into *out; a callback's bad value is an
 * error recorded on the field's context (CVM_E_ARGUMENT, _INPUT_NONFINITE). */
cvm_status cvm__g3_size_at(const cvm__g3_size *z, const double *x, double *out);
/* The smallest size the field can give (the smallest l(f), or h; or a user
 * source's size), not counting a callback. */
double cvm__g3_size_min(const cvm__g3_size *z);
/* 1 when the field follows the surface's triangles. */
int cvm__g3_size_follows(const cvm__g3_size *z);
/* The user sizing, or NULL. */
const cvm_sizing *cvm__g3_size_user(const cvm__g3_size *z);
/* The grading g (any positive value for a uniform field). */
double cvm__g3_size_grading(const cvm__g3_size *z);

/* ---- g3_grid.c: points in a uniform hash grid, for "is any point within r" ---- */
typedef struct cvm__g3_grid cvm__g3_grid;
cvm_status cvm__g3_grid_create(cvm__g3_grid **out, cvm__ctx *ctx, double cell);
void cvm__g3_grid_free(cvm__g3_grid *g);
/* Add point id (its coordinates are read from xyz[3 id] on queries). */
cvm_status cvm__g3_grid_add(cvm__g3_grid *g, const double *xyz, int32_t id);
/* 1 when some added point lies strictly closer than r to x. */
int cvm__g3_grid_near(const cvm__g3_grid *g, const double *xyz, const double *x, double r);

/* The cell along one axis of a uniform grid (cells of edge `cell` from lo, dim of
 * them) holding coordinate v, clamped to [0, dim - 1] (NaN: 0). */
static inline int64_t cvm__g3_cell_at(double v, double lo, double cell, int64_t dim)
{
    double t = floor((v - lo) / cell);
    if (!(t >= 0))
        return 0;
    if (t >= (double)dim)
        return dim - 1;
    return (int64_t)t;
}

/* ---- g3_trigrid.c: surface triangles in a uniform grid, for "is any triangle within r" ---- */
typedef struct cvm__g3_trigrid cvm__g3_trigrid;
/* A grid answering queries of radius at most reach about s (which it keeps a pointer
 * to). CVM_E_NOMEM, CVM_E_TOO_LARGE. */
cvm_status cvm__g3_trigrid_create(cvm__g3_trigrid **out, cvm__ctx *ctx, const cvm__g3_surface *s,
                                  double reach);
void cvm__g3_trigrid_free(cvm__g3_trigrid *g);
/* 1 when a triangle of the surface lies closer than r (<= reach) to x. */
int cvm__g3_trigrid_near(const cvm__g3_trigrid *g, const double *x, double r);

/* ---- g3_inside.c: exact point-in-domain by ray parity ---- */
typedef struct cvm__g3_inside cvm__g3_inside;
cvm_status cvm__g3_inside_create(cvm__g3_inside **out, cvm__ctx *ctx, const cvm__g3_surface *s);
void cvm__g3_inside_free(cvm__g3_inside *in);
/* 1 when x lies strictly inside the domain (an odd number of surface
 * crossings of a segment from x to beyond the bounding box); 0 outside, on
 * the surface, or when every trial ray met an edge or vertex exactly. */
int cvm__g3_is_inside(const cvm__g3_inside *in, const double *x);

/* ---- growing point list ---- */
typedef struct cvm__g3_points {
    double *xyz;  /* 3 n */
    double *dm;   /* n: rejection distance of each point (0 for surface points) */
    size_t n, cap;
} cvm__g3_points;
cvm_status cvm__g3_points_push(cvm__ctx *ctx, cvm__g3_points *P, const double *x, double dm);
void cvm__g3_points_free(cvm__ctx *ctx, cvm__g3_points *P);

/* ---- g3_near.c ---- */
/* Append the near-field points to P (which holds the surface points first):
 * pair surface triangles by maximum-cardinality matching, place one point
 * per pair or unmatched triangle, keep it when inside and farther than its dm
 * from every point of P. CVM_E_UNSUPPORTED when an edge has other than two
 * triangles (internal facets); CVM_E_NOMEM. */
cvm_status cvm__g3_near_field(cvm__ctx *ctx, const cvm__g3_surface *s, const cvm__g3_inside *in,
                              double wallf, cvm__g3_points *P, cvm__g3_report *rep);
/* The near field's distance from the surface over its offset delta, below which a
 * point is not placed (see g3_near.c). */
#define CVM__G3_NEAR_WALL 0.7

/* ---- g3_lattice.c ---- */
/* Append the free-space lattice points to P; a point of size hs is rejected within
 * dmf hs of another (dmf <= 0: cvm__g3_lattice_dm()'s 0.55). */
cvm_status cvm__g3_lattice(cvm__ctx *ctx, const cvm__g3_surface *s, const cvm__g3_size *z,
                           double h, double dmf, const cvm__g3_inside *in, cvm__g3_points *P,
                           cvm__g3_report *rep);
/* The lattice's rejection distance behind a re-meshed surface, over the size: the
 * near field of near-equilateral triangles lies 2/3 of the size deep, and 0.55 kept
 * lattice points 1/3 of the size behind it, between its points (flat tetrahedra).
 * Chosen by measurement (README, "3D mesh generation"; docs/benchmarks.md). */
#define CVM__G3_DM_REMESHED 0.65
/* The rejection distance of a lattice point of size hs: 0.55 hs (chosen by
 * measurement, see g3_lattice.c). */
double cvm__g3_lattice_dm(double hs);

/* ---- g3_octree.c ---- */
/* Append the free-space octree's centroids to P (see g3_octree.c): the
 * surface's bounding cube split while an octant's edge exceeds the size at
 * its centre, 2:1-balanced across faces (balance 6) or faces, edges and
 * corners (26); a leaf's centroid kept as a lattice point is. CVM_E_TOO_LARGE
 * past CVM__T3_MAX_POINTS, CVM_E_NOMEM, or a sizing callback's status. */
cvm_status cvm__g3_octree(cvm__ctx *ctx, const cvm__g3_surface *s, const cvm__g3_size *z,
                          double h, int balance, int split_hanging, const cvm__g3_inside *in,
                          cvm__g3_points *P, cvm__g3_report *rep);

/* ---- g3_refine.c ---- */
/* The squared distance from p to the triangle abc (plain doubles). */
double cvm__g3_tri_dist2(const double *p, const double *a, const double *b, const double *c);
/* Append the free space by Delaunay refinement to P (see g3_refine.c): rounds
 * of circumcentres of the tetrahedra of P whose circumradius exceeds the
 * size, kept by the lattice's rules and away from the surface triangles.
 * limit: at most this many points (0: none); *limited is 1 when it stopped
 * the rounds. CVM_E_TOO_LARGE, CVM_E_NOMEM, a kernel or sizing callback status. */
cvm_status cvm__g3_refine(cvm__ctx *ctx, const cvm__g3_surface *s, const cvm__g3_size *z,
                          double h, const cvm__g3_inside *in, size_t limit, uint64_t seed,
                          cvm__g3_points *P, cvm__g3_report *rep, int *limited);

/* ---- g3_recover.c ---- */
/* Remove generated points (P beyond the first s->np) until every surface
 * triangle is a face of the Delaunay tetrahedralisation of P (at most a few
 * rounds, each dropping the points inside a sphere through the missing
 * triangle). CVM_E_UNSUPPORTED naming the triangle (0-based index into
 * s->tri) in *bad_face when one stays missing, CVM_E_NOMEM, or a kernel status. */
cvm_status cvm__g3_recover(cvm__ctx *ctx, const cvm__g3_surface *s, cvm__g3_points *P,
                           uint64_t seed, cvm__g3_report *rep, int64_t *bad_face);

/* ---- g3_surface.c: planar facets re-meshed by the 2D frontal refiner ---- */
typedef struct cvm__g3_remeshed {
    double *xyz;            /* 3 np: the points of the new surface (NULL: keep the input) */
    size_t np;
    int32_t *tri;           /* 3 nt, oriented as the input's triangles */
    int32_t *tsrc;          /* nt: an input triangle of the facet each comes from */
    size_t nt;
    size_t facets_remeshed; /* planar facets of 2+ triangles re-meshed */
    size_t tris_before, tris_after;
    size_t rounds;          /* meshing rounds (boundary splits by the refiner add one) */
} cvm__g3_remeshed;
/* Re-mesh the planar facets of s (see g3_surface.c) at the size field of p.
 * key: NULL, or nt values; only triangles of equal key join a facet. The
 * result is in out (out->xyz NULL when nothing was re-meshed: no facet of 2+
 * coplanar triangles with one simple boundary loop, or one whose 2D
 * triangulation failed on rounding). CVM_E_NOMEM, or a refiner status. */
cvm_status cvm__g3_remesh_planar(cvm__ctx *ctx, const cvm__g3_surface *s, const int32_t *key,
                                 const cvm__g3_params *p, cvm__g3_remeshed *out);
void cvm__g3_remeshed_free(cvm__ctx *ctx, cvm__g3_remeshed *r);

/* ---- g3_remesh.c: the whole surface re-meshed isotropically ---- */
/* Re-mesh every triangle of s (see g3_remesh.c) at a size that follows its
 * curvature, capped by p->h and the user sizing, graded by p->grading;
 * features (key changes, edges sharper than 35 degrees) kept. The result in
 * out (out->xyz NULL when s is no closed oriented 2-manifold); facets_remeshed
 * counts the smooth patches. CVM_E_NOMEM, or a user sizing's status. */
cvm_status cvm__g3_remesh_all(cvm__ctx *ctx, const cvm__g3_surface *s, const int32_t *key,
                              const cvm__g3_params *p, cvm__g3_remeshed *out);

/* ---- g3_run.c ---- */
/* The generated points (near field, then free space) in *out, without the
 * surface's points. check_faces: also run cvm__g3_recover (a build without
 * TetGen, whose boundary recovery needs every surface triangle as a Delaunay
 * face). */
cvm_status cvm__g3_generate(cvm__ctx *ctx, const cvm__g3_surface *s, const cvm__g3_params *p,
                            int check_faces, uint64_t seed, cvm__g3_points *out,
                            cvm__g3_report *rep, int64_t *bad_face);

#endif
