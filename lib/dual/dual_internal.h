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

#endif
