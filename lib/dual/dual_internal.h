/*
 * dual_internal.h - the power (weighted Voronoi) dual of a 2D triangulation:
 * the power vertex of a triangle (construction, inexact) and the exact test
 * that decides on which side of a triangle's edge that vertex lies.
 *
 * Convention: the power distance of x to the weighted point (p, w) is
 * |x - p|^2 - w (w in squared length units). The power vertex (orthocentre)
 * of a triangle has equal power distance to its three weighted corners; with
 * all weights 0 it is the circumcentre.
 */
#ifndef CVM_DUAL_INTERNAL_H
#define CVM_DUAL_INTERNAL_H

#include <stdint.h>
#include "delaunay/delaunay_internal.h"
#include "delaunay/domain.h"

/* Power vertex of the non-degenerate triangle a, b, c with weights wa, wb, wc
 * into out[2]: plain doubles, possibly inexact (a construction). */
void cvm__power_vertex2d(const double *a, const double *b, const double *c, double wa, double wb,
                         double wc, double *out);

/* Exact side of the power vertex V of triangle a, b, c (counter-clockwise,
 * non-degenerate) relative to its edge a-b: +1 when V lies strictly on c's side
 * of the line ab, 0 on it, -1 beyond it. It is the sign of
 *   |B|^2 (|C|^2 + wa - wc) - (B.C) (|B|^2 + wa - wb),   B = b - a, C = c - a,
 * which is 2 D (B x V) with D = B x C > 0 (derivation in power_side.c),
 * so its sign is that of orient2d(a, b, V); with zero weights it is the sign of (a - c).(b - c), i.e. +1
 * iff the angle at c is acute. A floating-point filter, then exact expansion
 * arithmetic; exact over the range of the predicates in geom_internal.h
 * (treat sqrt|w| as a coordinate). Pure. */
int cvm__power_side2d(const double *a, const double *b, const double *c, double wa, double wb,
                      double wc);

/* Power-bisector foot of edge a-b: the point of line ab with equal power
 * distance to (a, wa) and (b, wb), into out[2] (inexact; a != b). */
void cvm__power_foot2d(const double *a, const double *b, double wa, double wb, double *out);

/* ---- merging (merge.c) ---- */

/* Local size of every vertex of T from the mesh: the mean length of its
 * edges to other vertices of domain triangles (0 for a vertex without any),
 * into vsize (T->nv entries). The merge rule uses it, so any tool can
 * recompute merge decisions from the mesh alone. */
void cvm__dual_mesh_sizes(const cvm__tri2 *T, double *vsize);

/* Power vertex of slot t (a live real triangle) into out[2] (inexact). */
void cvm__dual_tri_vertex(const cvm__tri2 *T, int32_t t, double *out);

/* The one merge rule. Edge j of domain triangle t is mergeable when it is not
 * constrained, the triangle u across it is a domain triangle of the same
 * regional attribute, and the dual edge |V_t - V_u| is shorter than
 * tol * l / sqrt(3), l the mean of vsize at the edge's two ends. Vt, Vu are
 * the power vertices of t and u (the caller's, so it can cache them). */
int cvm__dual_edge_mergeable(const cvm__tri2 *T, const double *vsize, double tol, int32_t t, int j,
                             const double *Vt, const double *Vu);

/* The compliance classes of cvm__dual_tri_compliance (not a cvm_status). */
enum {
    CVM__DUAL_INSIDE = 0,   /* the power vertex lies inside or on the triangle */
    CVM__DUAL_MERGED = 1,   /* outside, but only beyond mergeable edges */
    CVM__DUAL_NONCOMPLIANT = 2
};

/* Compliance of domain triangle t: CVM__DUAL_INSIDE when its power vertex
 * lies inside or on it (exact cvm__power_side2d on each edge),
 * CVM__DUAL_MERGED when outside but every edge it lies beyond is mergeable
 * (the merged cell holds it), CVM__DUAL_NONCOMPLIANT otherwise.
 * V: cache of power vertices by slot (2 per slot, filled for domain slots). */
int cvm__dual_tri_compliance(const cvm__tri2 *T, const double *vsize, double tol, const double *V,
                             int32_t t);

/* Merge groups by slot: group[t] = the smallest slot of the group of domain
 * triangles joined by mergeable edges (union-find), t itself when unmerged,
 * -1 for slots that are not domain triangles. group has T->nt entries; V as
 * above. CVM_OK or CVM_E_NOMEM. */
cvm_status cvm__dual_merge_groups(cvm__ctx *ctx, const cvm__tri2 *T, const double *vsize, double tol,
                                  const double *V, int32_t *group);

/* ---- the dual optimiser (optimise*.c, topology.c) ---- */

/* 1 when vertex v can be removed by cvm__dual_remove_vertex: it has at least
 * three triangles, all domain triangles of one region, and none of its edges
 * is constrained (so it is no hull, segment or region-border vertex); its
 * number of triangles into *deg (may be NULL). */
int cvm__dual_removable(const cvm__tri2 *T, int32_t v, size_t *deg);

/* Remove v (see cvm__dual_removable) by flips of its edges down to three
 * triangles and the 3-to-1 flip (topology.c); avoid: a vertex that should
 * gain no edge (-1: none). 1 removed (v then has vtri -1; the triangulation
 * is valid, possibly not regular), 0 not removable. Exact orient2d. */
int cvm__dual_remove_vertex(cvm__tri2 *T, int32_t v, int32_t avoid);

/* Layer of every slot of T: 0 for the domain triangles with a vertex flagged
 * in vbnd (T->nv entries), k + 1 for the domain triangles sharing an edge with
 * a layer-k triangle and in no lower layer (breadth-first), INT32_MAX for
 * domain triangles never reached and for every other slot. queue: scratch of
 * T->nt entries. Deterministic (slot order). */
void cvm__dual_layers(const cvm__tri2 *T, const uint8_t *vbnd, int32_t *layer, int32_t *queue);

enum { CVM__DUAL_SOLVER_PATTERN = 1, CVM__DUAL_SOLVER_CUCKOO = 2 };

/* Size callback of the optimiser: the local size at (x, y) into *h; a status
 * other than CVM_OK stops the run with it (the callee records the message). */
typedef cvm_status (*cvm__dual_size_fn)(void *payload, double x, double y, double *h);

typedef struct cvm__dual_opt_params {
    int solver;             /* CVM__DUAL_SOLVER_* */
    int max_sweeps;
    double min_angle_deg;   /* feasibility bound of the local solver */
    double target_angle_deg; /* triangles with a smaller angle are visited and penalised */
    int cuckoo_budget;      /* objective evaluations per vertex (cuckoo) */
    int pattern_budget;     /* objective evaluations per vertex (pattern search) */
    double margin;          /* power vertex pushed this fraction of each edge inside */
    double merge_tol;       /* fraction of l / sqrt(3) */
    double layer_priority;  /* c of L = 1 + c / (1 + layer) */
    uint64_t seed;
    int threads;            /* OpenMP threads for the local problems (0: default) */
    size_t n_fixed;         /* vertices 0..n_fixed-1 keep their position (input points
                               with CVM_OPT_DUAL_KEEP_INPUT_POINTS), else 0 */
    size_t n_input;         /* vertices 0..n_input-1 are input points: never removed */
    int topology;           /* CVM_OPT_DUAL_TOPOLOGY: 1 vanished vertices removed, 2 and
                               degree repair, 0 no vertex removed */
    int32_t *vmap;          /* T->nv entries (the count at the call), needed when
                               topology is 1: on return old vertex id -> new id, -1
                               for a removed vertex (T's vertices are renumbered in
                               order by cvm__tri2_compact) */
    int prepass;            /* CVM_OPT_DUAL_PREPASS: run cvm__dual_prepass first (needs vmap) */
    int maxmin_rounds;      /* CVM_OPT_DUAL_MAXMIN_ROUNDS: rounds of the max-min-angle phase */
    int maxmin_trials;      /* CVM_OPT_DUAL_MAXMIN_TRIALS: removal-trial calls after them */
    cvm__dual_size_fn size_fn; /* NULL: sizes from the mesh (cvm__dual_mesh_sizes) */
    void *size_payload;
} cvm__dual_opt_params;

typedef struct cvm__dual_opt_report {
    size_t sweeps;
    double nc_before_pct, nc_after_pct; /* % non-compliant (outside and not mergeable) */
    size_t moves;           /* accepted local moves */
    size_t flips;           /* flips restoring the regular triangulation */
    size_t weight_fixes;    /* weights raised so that no vertex vanishes */
    size_t removed_vanished; /* vertices removed because their power cell vanished */
    size_t removed_degree;  /* vertices removed to repair a vertex degree */
    size_t prepass_removed; /* Steiner vertices removed by the pre-pass */
    size_t prepass_added;   /* vertices inserted by the pre-pass */
    size_t maxmin_rounds;   /* rounds of the max-min-angle phase run */
    size_t removed_maxmin;  /* vertices removed by its kept removal trials */
    double seconds;
} cvm__dual_opt_report;

/* Topology pre-pass (prepass.c): collapse Steiner vertices with an edge
 * shorter than 0.5 x the local size, re-seed the Steiner vertices of triangles
 * below min(35, p->target_angle_deg) degrees at the mean of their neighbours,
 * split unconstrained edges longer than 1.5 x the local size at their
 * midpoint; local size from p->size_fn, else the mean edge length. Input
 * points (ids < p->n_input) and constrained edges are never touched. Removed
 * vertices are dropped (ids renumbered in order; p->vmap, nv0 entries already
 * holding old id -> current id, follows); inserted ones are appended. Does
 * nothing without p->vmap. On return T is Delaunay/regular up to vertices the
 * weights would drop. CVM_OK, CVM_E_NOMEM, a size_fn error. Deterministic. */
cvm_status cvm__dual_prepass(cvm__tri2 *T, const cvm__dual_opt_params *p, size_t nv0,
                             size_t *removed, size_t *added);

/* Optimise positions and weights of the vertices of T (see
 * cvm_mesh_optimise_dual). Run control through T->ctx (armed by the caller).
 * On every return T is a valid regular triangulation with no vanished
 * vertex. CVM_OK, CVM_E_NOMEM, a size_fn error, CVM_INCOMPLETE_*. */
cvm_status cvm__dual_optimise(cvm__tri2 *T, const cvm__dual_opt_params *p, cvm__dual_opt_report *rep);

/* ---- the dual as geometry and measures (geometry.c, cells.c, quality.c) ---- */

/* Weight of vertex v (0 without weights). */
static inline double cvm__dual_weight(const cvm__tri2 *T, int32_t v)
{
    return T->w ? T->w[v] : 0.0;
}

/* 1 when slot t contains its power vertex (closed: on an edge counts); exact. */
int cvm__dual_tri_contains(const cvm__tri2 *T, int32_t t);

/* Signed area of the power cell of every vertex of T, restricted to the
 * domain, into dst (T->nv entries): the kites of each domain triangle's
 * power vertex and its edges' power-bisector feet. Constructions. */
void cvm__dual_areas(const cvm__tri2 *T, double *dst);

/* Ends of the dual edge of every edge of e (from cvm__domain_edges with
 * constrained_only = 0), 4 doubles per edge into ends: the power vertices of
 * its two triangles (the first in slot order first), or for a boundary edge
 * the power vertex of its triangle and the edge's power-bisector foot.
 * Constructions: plain doubles. CVM_OK or CVM_E_NOMEM (no message). */
cvm_status cvm__dual_edge_ends(cvm__ctx *ctx, const cvm__tri2 *T, const cvm__edges *e, double *ends);

/* The dual cell polygons of every vertex of T (cells.c): off
 * (nv + 1 entries) receives the CSR offsets; xy, when not NULL, receives 2
 * doubles per corner (2 * off[nv]). CVM_OK, CVM_E_NOMEM or CVM_E_TOO_LARGE
 * (no message). */
cvm_status cvm__dual_cells(cvm__ctx *ctx, const cvm__tri2 *T, int32_t *off, double *xy);

/* The power dual of the domain of T as a finite-volume mesh (cells.c), its
 * corners shared. Points: the power vertex of every domain triangle (output
 * order), then the power-bisector foot of every boundary edge (edge order of
 * cvm__domain_edges), then every vertex on a boundary edge (vertex order).
 * Cells: one per vertex, the corners of cvm__dual_cells() as point ids (the
 * same doubles). Faces, 6 ints each: cell a, cell b (-1 on the boundary), the
 * primal edge (its two vertices), the face's two points p, q, cell a on the
 * left of p -> q; first one per domain edge in edge order (a < b its
 * vertices; on a boundary edge the face joins the foot and the power vertex),
 * then per boundary edge (s, h) counter-clockwise around the domain two
 * boundary faces: (s, -1, s, h, s, foot) and (h, -1, h, s, foot, h). flen, 2
 * per face: the primal edge length and the face length (plain doubles). */
typedef struct cvm__dual_fv {
    double *pt;       /* 2 * npt */
    size_t npt, ntri, nbedge, nbvert;
    int32_t *off;     /* nv + 1 */
    int32_t *corner;  /* off[nv] point ids */
    int32_t *face;    /* 6 * nface */
    double *flen;     /* 2 * nface */
    size_t nface;
} cvm__dual_fv;

/* Build fv from T. CVM_OK, CVM_E_NOMEM or CVM_E_TOO_LARGE (no message); on
 * error fv is zeroed. */
cvm_status cvm__dual_fv_build(cvm__ctx *ctx, const cvm__tri2 *T, cvm__dual_fv *fv);
void cvm__dual_fv_free(cvm__ctx *ctx, cvm__dual_fv *fv);

/* A view of T for dimensionless dual measures (quality.c): when
 * the coordinates of T reach beyond 2^300 or all lie below 2^-300 (the
 * constructions of the dual form cubes of coordinate differences, which
 * would overflow or underflow), *view is a shallow copy of T whose
 * coordinates are scaled by 2^-*k and weights by 2^-2*k, in fresh arrays;
 * otherwise *view = *T and *k = 0. A power-of-two scale is exact (up to
 * subnormal parts) and leaves every ratio unchanged. Read-only; release with
 * cvm__scaled_view_free(). CVM_OK or CVM_E_NOMEM (no message). */
cvm_status cvm__scaled_view(cvm__ctx *ctx, const cvm__tri2 *T, cvm__tri2 *view, int *k);
void cvm__scaled_view_free(cvm__ctx *ctx, const cvm__tri2 *T, cvm__tri2 *view);

/* Dual edge length of every edge of e (from cvm__domain_edges with
 * constrained_only = 0) into len (e->n entries). CVM_OK or CVM_E_NOMEM. */
cvm_status cvm__dual_edge_lengths(cvm__ctx *ctx, const cvm__tri2 *T, const cvm__edges *e, double *len);

/* pct[0]: % of the domain triangles whose power vertex lies outside them;
 * pct[1]: the same among those with a vertex on the domain boundary (0 when
 * there are none). CVM_OK or CVM_E_NOMEM. */
cvm_status cvm__dual_outside_pct(cvm__ctx *ctx, const cvm__tri2 *T, double *pct);

/* Every dual quality value of a mesh (quality.c; definitions in
 * include/cvmesh.h, cvm_histogram). */
typedef struct cvm__dual_q {
    size_t nt, ne;
    double *q[6];  /* q[1], q[2]: nt values; q[3..5]: ne values; q[0] unused */
    uint8_t *tb;   /* nt: the triangle has a vertex on the domain boundary */
    uint8_t *eint; /* ne: interior edge (a domain triangle on both sides) */
    uint8_t *eb;   /* ne: an endpoint lies on the domain boundary */
} cvm__dual_q;

/* Compute every value of d for the domain of T (in the frame of
 * cvm__scaled_view), and when minima is not NULL over the interior edges:
 * the smallest dual edge (minima[0]), the smallest min(primal, dual)
 * (minima[1]) and the smallest dual / primal ratio (minima[2]); 0 without
 * interior edges. CVM_OK or CVM_E_NOMEM (d then empty). */
cvm_status cvm__dual_q_compute(cvm__ctx *ctx, const cvm__tri2 *T, cvm__dual_q *d, double *minima);
void cvm__dual_q_free(cvm__ctx *ctx, cvm__dual_q *d);
/* Bins of histogram w (1..5): count, width; the last bin of q2..q5 is open. */
void cvm__dual_q_bins(int w, size_t *n, double *width);
/* Histogram w (1..5) of d into dst (its cvm__dual_q_bins() count of entries);
 * q3..q5 count interior edges only. */
void cvm__dual_q_histogram(const cvm__dual_q *d, int w, double *dst);
/* Smallest, largest and mean of q[w] over the triangles (w < 3) or interior
 * edges, only those touching the boundary when boundary_only. */
typedef struct cvm__dual_q_summary {
    double min, max, mean;
} cvm__dual_q_summary;
cvm__dual_q_summary cvm__dual_q_summarise(const cvm__dual_q *d, int w, int boundary_only);

#endif
