/*
 * optimise.h - the parts of the dual optimiser shared by its files: the run
 * state (optimise_run.h), the local problem of one vertex and its objective
 * (optimise_objective.c), and the two local solvers (optimise_pattern.c,
 * optimise_cuckoo.c).
 *
 * The local problem of vertex v: its degrees of freedom are scaled so that
 * one unit is the local size h in position and h^2 in weight. ndof 3: an
 * interior Steiner vertex, u = (dx, dy, dw); ndof 2: a Steiner vertex on a
 * segment, u = (ds, dw) along the segment's direction; ndof 1: an input
 * vertex, u = (dw). The objective is a smooth penalty, a plain-double
 * measure; every candidate whose star would invert is rejected by the exact
 * orient2d, so floating point only chooses which valid mesh results.
 */
#ifndef CVM_DUAL_OPTIMISE_H
#define CVM_DUAL_OPTIMISE_H

#include "dual_internal.h"

#define CVM__DOPT_MAXDOF 3

/* Stars larger than this are not solved by the max-min-angle phase. */
#define CVM__DOPT_MM_MAXSTAR 48

typedef struct cvm__dopt_local {
    const cvm__tri2 *T;
    int32_t v;
    int ndof;
    double p0[2], w0;      /* start position and weight */
    double h;              /* scale */
    double dir[2];         /* unit direction of the segment (ndof 2) */
    const int32_t *star;   /* live triangles around v (ghosts included) */
    size_t nstar;
    const uint8_t *vbnd;   /* per vertex: 1 on the domain boundary (priority) */
    double sin2_bound;     /* smallest sin^2 of an angle a candidate may create */
    double sin2_target;    /* angles below this are penalised */
    double margin;         /* fraction of each edge the power vertex should keep inside */
    size_t evals;          /* evaluations so far */
    /* max-min-angle phase (see cvm__dopt_eval_maxmin): */
    int maxmin;            /* 1: cvm__dopt_eval is cvm__dopt_eval_maxmin */
    double slack_bound;    /* smallest containment slack a candidate may leave */
    double dual_bound;     /* smallest dual/primal edge ratio a candidate may leave */
    double mm_m0;          /* smallest sin^2 of the star at the start: never less */
    int vnb_ok;            /* 1: vnb holds the power vertices across the star's edges */
    double vnb[6 * CVM__DOPT_MM_MAXSTAR]; /* per star triangle and edge: the power vertex of
                                             the domain triangle across when it is not in the
                                             star (it does not move with v) */
} cvm__dopt_local;


/* Position and weight of v at scaled offset u into p[2], *w. */
void cvm__dopt_point(const cvm__dopt_local *L, const double *u, double *p, double *w);

/* Local objective at u: HUGE_VAL when infeasible (a star triangle not
 * strictly counter-clockwise by exact orient2d, an angle below the bound in a
 * domain triangle, or the power cell of v empty inside its star), else the
 * penalty sum over the domain triangles of the star. Counts an evaluation. */
double cvm__dopt_eval(cvm__dopt_local *L, const double *u);
/* The same, but it may stop early and return a value >= bound (not the
 * objective) as soon as the partial sum reaches bound: every term is >= 0, so
 * a caller that only asks "below bound?" gets the same answer, sooner. */
double cvm__dopt_eval_below(cvm__dopt_local *L, const double *u, double bound);

/* The max-min-angle objective at u: HUGE_VAL when a star triangle would not
 * be strictly counter-clockwise (exact orient2d), an unconstrained edge of the
 * star or of its outline would fail the exact power test (so the star stays
 * regular and no flip follows the move), the power vertex of a domain
 * triangle would keep less than slack_bound x an edge's length inside that
 * edge, or a dual edge across an edge of the star between two domain
 * triangles would be shorter than dual_bound x that edge; else minus the
 * smallest sin^2 of an angle of the star's domain triangles, minus a small
 * multiple of the smallest containment slack (so a weight move that makes
 * room counts). Counts an evaluation. With slack_out (may be NULL) the
 * measured smallest slack and dual ratio are written to slack_out[0..1] and
 * the bounds are not applied. */
double cvm__dopt_eval_maxmin(cvm__dopt_local *L, const double *u, double *slack_out);

/* Fill L->vnb (the power vertices across the star's outer edges, which no
 * candidate of v moves) and set L->vnb_ok; stars above CVM__DOPT_MM_MAXSTAR
 * are left alone. */
void cvm__dopt_maxmin_cache(cvm__dopt_local *L);

/* The position solver of the max-min-angle phase (L->maxmin set, ndof 2 or
 * 3): Freitag's active-set ascent on the sines of the angles of the star's
 * domain triangles, weight unchanged, every step checked by cvm__dopt_eval
 * (exact orientation and regularity, the bounds); from u = 0 with value f0,
 * the best point into u and its value into *f. */
void cvm__dopt_maxmin_active(cvm__dopt_local *L, double f0, double *u, double *f);

/* Smallest sin^2 of an angle over the domain triangles of the star at u = 0. */
double cvm__dopt_star_min_sin2(const cvm__dopt_local *L);

/* Deterministic compass (pattern) search from u = 0 with at most budget
 * evaluations; writes the best point to u and its value to *f (the value
 * at 0 is f0). */
void cvm__dopt_pattern(cvm__dopt_local *L, int budget, double f0, double *u, double *f);

/* Modified Cuckoo Search (Walton, Hassan, Morgan, Brown 2011) from u = 0 with
 * at most budget evaluations and the random stream r; as above. */
void cvm__dopt_cuckoo(cvm__dopt_local *L, int budget, cvm__rng *r, double f0, double *u, double *f);

#endif
