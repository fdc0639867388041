/*
 * optimise_run.h - the run state of the dual optimiser (optimise.c) and the
 * operations its phase files share: scoring and the vertex problems
 * (optimise_score.c), sweeps, restores and degree repair (optimise_sweep.c),
 * the max-min phase with its removal trials (optimise_removal.c) and the
 * best-state bookkeeping (optimise_best.c). The algorithm is described in
 * optimise.c, which drives the run.
 */
#ifndef CVM_DUAL_OPTIMISE_RUN_H
#define CVM_DUAL_OPTIMISE_RUN_H

#include "optimise.h"

#define FIX_ROUNDS 8
#define BATCH 256
#define DEG_HIGH_DEG 47.0 /* average corner angle that calls for degree repair */
#define DEG_SWEEPS 10     /* degree repair after the first DEG_SWEEPS sweeps only */
#define PATIENCE 4        /* sweeps without progress before the run stops */
#define PUSHES 1          /* target raises before the run ends */
#define PUSH_PATIENCE 2   /* PATIENCE after a raise: 4 gave nearly the same results
                             for more time (docs/design/dual_optimisation.md) */
#define PROGRESS_DEG 0.05 /* smallest-angle gain over PATIENCE sweeps that keeps the run going */
#define PUSH_DEG 5.0      /* each raise of the target angle, degrees */
#define BEST_EPS_DEG 1e-3 /* smallest angle gain that makes a state the new best, degrees */
#define MM_BAND_DEG 2.0   /* max-min phase: visit triangles below the smallest angle + this */
#define MM_PATIENCE 3     /* max-min phase: rounds without MM_PROGRESS_DEG gain before it ends */
#define MM_PROGRESS_DEG 0.01
#define MM_SLACK_F (1.0 / 3.0) /* max-min phase: containment slack kept, x the margin */
#define MM_DUAL_F 1.1     /* max-min phase: dual/primal edge ratio kept, x the margin */
#define MM_PATTERN_BUDGET 20 /* max-min phase: compass evaluations after the active-set ascent */
#define RM_BAND_DEG 0.5   /* removal trials: corners of triangles below the smallest angle + this */
#define RM_TRIES 8        /* removal trials: at most this many per call */
#define RM_SWEEPS 8       /* removal trials: penalty sweeps to regain compliance */
#define RM_ROUNDS 15      /* removal trials: max-min rounds before a trial is judged */
#define RM_FAILED 64      /* removal trials: failed positions remembered (not tried again) */
#define RM_HUB_DEG 8      /* removal trials: triangles around a vertex that make it a hub */
#define RM_RINGS 4        /* removal trials: rings around the removed vertex its rounds visit */
#define RM_MAXNB 96       /* removal trials: neighbour slots (a star's corners, repeats included) */

/* One vertex of a batch: its star (in the batch's pool) and the outcome of its
 * local problem. */
typedef struct job {
    int32_t v;
    size_t star0, nstar;
    int moved;
    double p[2], w;
} job;

typedef struct dopt {
    cvm__tri2 *T;
    const cvm__dual_opt_params *p;
    double *vsize;   /* nv: the local size (the sizing's where given, else msize) */
    double *msize;   /* nv: the mesh's own sizes (cvm__dual_mesh_sizes), which the merge
                        rule of the compliance measures uses (cvm_mesh_copy_dual_merge_groups()):
                        the sweeps score with them, so the state they keep as the best
                        is the best by the report's measure */
    uint8_t *vbnd;   /* nv: on the domain boundary */
    uint8_t *mark;   /* nv: scratch (visited / vanished) */
    double *V;       /* 2 per slot */
    double *F;       /* per slot */
    uint8_t *st;     /* per slot: cvm__dual_tri_compliance */
    int32_t *layer;  /* per slot: cvm__dual_layers */
    uint8_t *weak;   /* per slot: compliant but an angle below the target, merged, or the
                        power vertex within half the margin of an edge */
    int32_t *list;   /* slots to visit */
    int32_t *star;   /* scratch: sort buffer, then the stars of a batch (disjoint) */
    struct job *jobs; /* BATCH entries */
    uint32_t *stamp; /* nv: batch stamp of the vertices a batch holds or touches */
    uint8_t *gone;   /* nv: removed, not yet compacted */
    uint8_t *region; /* nv: removal trials: the vertices whose triangles its rounds visit */
    int region_on;   /* 1: max-min rounds visit only triangles with a vertex in region */
    int32_t *dup, *map2; /* nv: scratch of compact() */
    size_t nv0;      /* vertex count at the call (vmap's length) */
    int topo;        /* vertex removal on (p->topology with p->vmap) */
    uint32_t cur_stamp;
    int nthreads;
    double *save;    /* 3 per vertex: x, y, w at the start of a sweep */
    double *best;    /* 3 per vertex: x, y, w of the best state (keep_best) */
    size_t best_nv, best_removed;
    /* the best state's triangulation (keep_best), for best_cap slots: its
     * positions may turn over triangles that later flips made, which flips
     * cannot untangle; best_nt 0 when none is kept */
    int32_t *best_tv, *best_tn, *best_te, *best_vtri;
    uint8_t *best_tf;
    double *best_ta;
    size_t best_nt, best_cap;
    int32_t best_last;
    size_t nc, nc0;  /* current and initial non-compliant counts */
    size_t nweak;
    double sin2_min, sin2_target;
    int mm;          /* 1 during the max-min-angle phase (maxmin_phase) */
    double mm_min;   /* smallest angle when its round's order was made, degrees */
    int nc_only;     /* 1: a sweep visits the non-compliant triangles only */
    struct snap *snap; /* removal trials: the state to go back to */
    double failed[2 * RM_FAILED]; /* removal trials: positions of vertices whose trial failed */
    size_t nfailed;
    cvm__dual_opt_report *rep;
} dopt;

/* Key of the random stream of (seed, sweep, vertex): the shuffles depend on
 * these alone, never on threads or addresses. */
uint64_t cvm__dopt_stream_key(uint64_t seed, uint64_t sweep, uint64_t v);

/* The local size of every vertex into D->vsize: the mesh's own, replaced by
 * p->size_fn where it gives a positive finite size. CVM_OK or its error. */
cvm_status cvm__dopt_sizes(dopt *D);

/* D->vbnd: 1 for the vertices on the domain boundary. */
void cvm__dopt_boundary_flags(dopt *D);

double cvm__dopt_sq(double x);

/* Re-score slot t (a domain triangle), keeping the non-compliant and weak counts. */
void cvm__dopt_rescore(dopt *D, int32_t t);

/* Score every domain triangle (see optimise.c) and count the non-compliant
 * and weak ones, with the mesh's own sizes at the current positions (msize). */
void cvm__dopt_score_all(dopt *D);

/* Live triangles around v into star (room for them); their number. */
size_t cvm__dopt_gather_star(const dopt *D, int32_t v, int32_t *star);

/* Degrees of freedom of v (see optimise.h) and, for a vertex on a segment,
 * the segment's direction. 0: v has no domain triangle. */
int cvm__dopt_vertex_mode(const dopt *D, int32_t v, const int32_t *star, size_t n, double *dir);

/* Drop the removed vertices (gone) from T's vertex arrays, renumbering the
 * rest in order; carry vsize, vbnd and the caller's map along. */
void cvm__dopt_compact(dopt *D);

/* Make T regular again with no vanished vertex (see the file comment). */
cvm_status cvm__dopt_restore(dopt *D);

/* Degree repair (see the file comment): a vertex whose corners average less
 * than DEG_HIGH_DEG degrees (degree 8 and more inside) and that touches a weak
 * triangle loses its removable Steiner neighbour of least degree; an interior
 * removable Steiner vertex of degree 4 or less is removed. One operation per
 * neighbourhood and pass (stamps); vertices in index order. The number
 * removed; T is then valid but maybe not regular (restore() follows). */
size_t cvm__dopt_repair_degrees(dopt *D);

/* Smallest sin^2 of an angle of triangle t (plain doubles), at most 1. */
double cvm__dopt_tri_min_sin2(const cvm__tri2 *T, int32_t t);

/* Positions and weights of every vertex into D->save (start of a sweep). */
void cvm__dopt_save_state(dopt *D);

/* Back to the positions and weights in D->save. */
void cvm__dopt_load_state(dopt *D);

/* Percentage of the domain triangles that are non-compliant. */
double cvm__dopt_pct(dopt *D);

/* One sweep; *moved_out receives the number of accepted moves. The visiting
 * order is cut into batches of at most BATCH vertices, no two of them equal or
 * adjacent, taken in order from the sorted list (a vertex that would join a
 * batch holding one of its neighbours closes the batch). The local problems of
 * a batch are independent, so they are solved in parallel; the moves are
 * then applied and re-scored in batch order. Batches depend only on the mesh
 * and the order, never on the thread count, so the result does not either. */
cvm_status cvm__dopt_sweep(dopt *D, uint64_t k, size_t *moved_out);

/* Smallest angle over the domain triangles, degrees (a measure). */
double cvm__dopt_min_angle(const dopt *D);

/* Go back to the best state kept by keep_best when it beats the current one
 * and has the same vertices: its positions and weights, made regular again
 * (the regular triangulation of a weighted point set is unique, so this is
 * the triangulation it had). The flips since then may have made triangles that
 * the old positions turn over (around clusters of nearly coincident points);
 * flips cannot untangle that, so the run then keeps its current state. */
cvm_status cvm__dopt_end_at_best(dopt *D, size_t best_nc, double best_min);

/* The best state so far (see run): fewest non-compliant, then largest
 * smallest angle. 1 when the current state is better (and is now the best). */
int cvm__dopt_keep_best(dopt *D, size_t *best_nc, double *best_min);

/* Free a snapshot of the removal trials (NULL is fine). */
void cvm__dopt_snap_free(cvm__ctx *ctx, struct snap *S);

/* The max-min-angle phase (see optimise.c) from sweep number k0, keeping the
 * best state. CVM_OK, CVM_E_NOMEM, a size error or a stop status. */
cvm_status cvm__dopt_maxmin_phase(dopt *D, uint64_t k0, size_t *best_nc, double *best_min);

#endif
