/*
 * dual3.h - the 3D power-dual optimiser (the 3D form of lib/dual's): move
 * vertices and set power weights of a tetrahedral mesh so that more
 * tetrahedra contain their power vertex (the "co-volume" property).
 *
 * Without flips (params.flips 0) the connectivity is kept: a move of vertex
 * v (x, y, z, w) is accepted only when every tetrahedron of v's star stays positively oriented
 * (exact orient3d), every face of the star that is not constrained stays
 * locally regular (exact power test with symbolic perturbation by vertex
 * index, as cvm_mesh_check() decides it: the vertex across the face is not in
 * conflict with the tetrahedron's orthosphere; a face that already failed
 * before the move may keep failing), no dihedral angle of the star drops below
 * min(min_dihedral, the star's smallest before), the star's exactly counted
 * non-compliant tetrahedra do not increase, and the star's penalty decreases.
 * A locally regular tetrahedralisation is the regular one of its vertices (in
 * the constrained sense along constrained faces), so the mesh stays regular
 * after every accepted move, every face (the surface included) stays a face,
 * and no power cell can vanish: a stop at any point leaves a valid mesh.
 * With flips, a move that leaves faces of the star not locally regular (all
 * its tetrahedra still positive) is followed by exact 2-3 / 3-2 / 4-4 flips of
 * unconstrained faces (d3_flip.c) until every face around v and of the new
 * tetrahedra is locally regular (or an unchanged face that failed before, by
 * the perturbation only), else undone; the counts, angle floor and penalty are
 * judged on the tetrahedra replaced against those replacing them.
 * Vertices on a constrained face keep their position, except, with slide, a
 * vertex all of whose constrained faces lie in one axis-aligned plane: it
 * moves in the two other coordinates, so it stays exactly in the plane, and
 * the orientation checks keep its surface triangles unfolded. Weights are free.
 *
 * Penalty of a tetrahedron with root-mean-square edge l and power vertex
 * barycentric coordinates b_i (heights h_i): sum_i max(0, margin l - b_i h_i)^2 / l^2 plus
 * 1e-3 |centroid - power vertex|^2 / l^2 (the 2D design's smooth penalty).
 * Score (sweep order) F_k = W_k L_k |C_k - V_k|, W_k 1 when non-compliant
 * (exact) else 0, L_k 2 at the boundary else 1.
 *
 * Solver (params.solver): compass search over (x, y, z, w) from steps l_v / 4 and l_v^2 / 2
 * (l_v the mean edge at v), halved on failure, budget evaluations per vertex;
 * or Modified Cuckoo Search (d3_cuckoo.c, cuckoo_budget evaluations), whose best
 * nests are then tried in order under the same checks; or both, the cuckoo
 * search only where the compass search found no move.
 * Sweeps visit the vertices of the non-compliant tetrahedra, worst score
 * first, in min(20, n / 25 + 1) bins shuffled within by a stream keyed by
 * (seed, sweep). One thread: the result depends only on the mesh and params.
 *
 * Memory: the context's allocator; CVM_E_NOMEM before any move, the mesh
 * unchanged. Run control: cvm__tick() per vertex solved (stage
 * CVM_STAGE_OPTIMISE_DUAL, fraction of the initially non-compliant fixed).
 */
#ifndef CVM_DUAL3_H
#define CVM_DUAL3_H

#include <stddef.h>
#include <stdint.h>

#include "common/common_internal.h"

typedef struct cvm__d3_mesh {
    double *xyz;            /* 3 nv, updated in place */
    double *w;              /* nv weights, updated in place */
    size_t nv;
    const int32_t *tet;     /* 4 ntet, each positively oriented */
    size_t ntet;
    const int32_t *nbr;     /* 4 ntet: 4 u + g across face f (opposite corner f), or -1 */
    const uint8_t *cface;   /* 4 ntet: 1 when the face is constrained (no neighbour, or an
                               internal facet of the surface) */
    const double *attr;     /* ntet region attributes, or NULL (the optimiser flips only
                               between tetrahedra of one region) */
} cvm__d3_mesh;

typedef struct cvm__d3_params {
    int max_sweeps;
    double min_dihedral_deg;
    int budget;             /* evaluations per vertex and sweep */
    double margin;          /* power vertex wanted margin x mean edge inside every face */
    uint64_t seed;
    int slide;              /* 1: vertices inside an axis-aligned planar facet move in it;
                               2: also those of smooth boundary patches, on the surface
                               as it was (d3_slide.c) */
    int flips;              /* 1: the connectivity may change (d3_flip.c) */
    int solver;             /* 1 compass search; 2 cuckoo search; 3 compass, then cuckoo
                               where the compass search found no move */
    int cuckoo_budget;      /* evaluations per vertex and sweep of the cuckoo search */
    int escalate;           /* on a stall the budget doubles, up to escalate x budget, and
                               every vertex is searched again; 1: a stall ends the run */
} cvm__d3_params;

typedef struct cvm__d3_report {
    size_t sweeps, moves;
    size_t ntet, nbnd;              /* tetrahedra; those with a face without neighbour */
    size_t out_before, out_after;   /* power vertex strictly outside (exact) */
    size_t bout_before, bout_after; /* the same among the boundary tetrahedra */
    size_t ntet_after, nbnd_after;  /* the same counts at the end (flips change them) */
    size_t flips, flips_start;      /* flips kept in all; those of the first pass */
} cvm__d3_report;

/* The connectivity after a run with flips: owned by the caller (the context's
 * allocator), ntet tetrahedra; attr NULL when the input had none. */
typedef struct cvm__d3_topo {
    int32_t *tet;
    double *attr;
    size_t ntet;
} cvm__d3_topo;

/* Optimise M in place (vertices and weights). With p->flips, *topo receives the
 * new connectivity (also on a stop; the caller frees it) and M's tet, nbr, cface
 * describe the old one; without, topo is untouched and may be NULL. *r is filled
 * also on a stop. No allocation after the first move: CVM_E_NOMEM means nothing moved.
 * @return CVM_OK, CVM_E_NOMEM (nothing moved), CVM_INCOMPLETE_TIME_LIMIT,
 *         CVM_INCOMPLETE_CANCELLED (moves so far kept; the mesh is valid). */
cvm_status cvm__d3_optimise(cvm__ctx *ctx, cvm__d3_mesh *M, const cvm__d3_params *p,
                            cvm__d3_report *r, cvm__d3_topo *topo);

/* 1 when the power vertex of tetrahedron t of M lies strictly outside it (exact). */
int cvm__d3_outside(const cvm__d3_mesh *M, size_t t);

/* ---- merged cells (d3_merge.c) ----
 * Face f of tetrahedron t is mergeable when it is shared with a tetrahedron u
 * (M->nbr), is not constrained (M->cface), t and u have the same region (when
 * region is not NULL), tol > 0, and either their power vertices coincide
 * (the exact power test of u's far corner against t ties) or the distance of
 * their power vertices (plain doubles) is < tol x 0.38 x l, l the mean over the
 * face's 3 corners of the mean length of the corner's edges (each edge once):
 * only the mesh decides, so any tool can recompute the groups. Groups: the
 * connected components over mergeable faces (union-find; the root is the
 * group's smallest tetrahedron). A group of >= 2 is kept when, for each of its
 * boundary faces (a face of a member whose other side is no member), every
 * vertex of the group lies on the face's inner side or on its plane, and so
 * does the group's dual vertex, the power vertex of its root (plain doubles,
 * then the exact orient3d of that point: non-strict); and no constrained face
 * lies between two members. A group that fails is dissolved: its tetrahedra
 * are unmerged (group[t] = t). A tetrahedron is compliant when its power vertex
 * lies inside it or on its boundary (exact, as CVM_MEASURE_CIRCUMCENTRE_OUTSIDE_PCT)
 * or lies outside only beyond faces that are mergeable within a kept group. */
typedef struct cvm__d3_merge_report {
    size_t ntet, nbnd;   /* tetrahedra; those with a face without neighbour */
    size_t ngroups;      /* kept groups of >= 2 tetrahedra */
    size_t nmerged;      /* tetrahedra in those groups */
    size_t ndissolved;   /* groups of >= 2 that failed the check */
    size_t nout, nbout;  /* power vertex strictly outside (exact); among the boundary ones */
    size_t nnc, nbnc;    /* non-compliant; among the boundary ones */
} cvm__d3_merge_report;

/* group: ntet entries, the root of each tetrahedron's kept group (t itself when
 * unmerged). M->w may be NULL (all weights 0). region: ntet or NULL.
 * @return CVM_OK or CVM_E_NOMEM (message set; group unset). */
cvm_status cvm__d3_merge(cvm__ctx *ctx, const cvm__d3_mesh *M, const double *region, double tol,
                         int32_t *group, cvm__d3_merge_report *r);

#endif
