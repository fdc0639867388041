/*
 * aflr_internal.h - the state, tuning constants and shared steps of the
 * advancing-front pass (aflr.c: set-up and the pass; aflr_front.c: the
 * quality of triangles, their front edges, the queue and point placement;
 * aflr_smooth.c: interleaved smoothing; aflr_layers.c: the edge layers of the
 * pass and the layer index of the output's cells). Only the refiner's AFLR
 * files include it.
 */
#ifndef CVM_REFINE_AFLR_INTERNAL_H
#define CVM_REFINE_AFLR_INTERNAL_H

#include <stddef.h>
#include <stdint.h>

#include "refine_internal.h"
#include "delaunay/tri2_store.h"

/* Good needs every edge shorter than this times the mean size at its ends. */
#define AF_SIZE_BAD 1.5
/* A candidate point closer than this times the base edge to a vertex is rejected. */
#define AF_PROX 0.7
/* The equilateral point's edge length: the local size within these bounds x the base edge. */
#define AF_SHRINK 0.8
#define AF_GROW 1.25
/* Off-centres are used above this requested angle (degrees). */
#define AF_SHAPE_MIN_DEG 1.0
/* Weight of layer and edge length against shape in the queue key. */
#define AF_TIE 1e-6
/* A skinny (not too big) triangle is treated only from a front edge at least
 * this times the local size long; shorter ones are left to the clean-up. */
#define AF_MIN_BASE 0.5
/* Triangle qualities. */
enum { AF_OK = 0, AF_BIG = 1, AF_SKINNY = 2 };
/* With neither a sizing nor CVM_OPT_MAX_AREA nothing bounds the pass but the
 * shortest input edge, and above about 30 degrees its points cascade down to
 * that scale over the whole domain (millions on the cylinder at 34 degrees,
 * where Delaunay refinement needs 557): the pass then stops after this many
 * points per vertex it started with (about what Delaunay refinement needs on
 * the example domains), and the Delaunay clean-up finishes. */
#define AF_SIZELESS_CAP 4
/* Layer "infinite". */
#define AF_INF INT32_MAX
/* Interleaved smoothing (CVM_OPT_AFLR_SMOOTH_LAYERS): relaxation and smart
 * (or max-min) sweeps per completed group of layers. */
#define AF_SM_RELAX 2
#define AF_SM_SWEEPS 2
#ifndef AF_SM_BACK
#define AF_SM_BACK 1
#endif
/* The next and the previous corner of a triangle (faster than % 3 in the hot loops). */
static const int af_n1[3] = {1, 2, 0}, af_n2[3] = {2, 0, 1};

typedef struct af_state {
    int32_t *sl;               /* per triangle slot, 3: layer of each edge */
    int32_t *sv;               /* per slot, 3: its vertices when sl was written (sl is
                                  valid while they match the slot's) */
    unsigned char *sq;         /* per slot: quality (AF_OK ...) of the triangle in it,
                                  valid with sl (vertices fixed during the pass) */
    size_t cap_sl, cap_sv, cap_sq; /* in elements */
    int32_t *lo;               /* scratch per star triangle: layer of its outer edge */
    size_t cap_lo;
    unsigned char *front;      /* per segment id: starts a front */
    size_t nfront;
    cvm__vertex_grid grid;
    size_t ngrid;              /* vertices 0..ngrid-1 are in the grid */
    double lmin0;              /* shortest domain edge when the pass started */
    /* interleaved smoothing, only with nsm > 0 (see af_layers_done) */
    int32_t nsm;               /* CVM_OPT_AFLR_SMOOTH_LAYERS */
    cvm__bad_queue later;      /* triangles queued for a front edge of layer >= done + nsm */
    int32_t *vlay;             /* per vertex: its layer (base edge's + 1), AF_INF: none */
    size_t cap_vlay;
    int32_t done;              /* vertex layers 1..done are complete (and were smoothed) */
    int32_t maxlay;            /* highest vertex layer made so far */
    uint8_t *mask;             /* scratch: per vertex */
    int32_t *list;             /* scratch: the vertices of a group */
    double *old;               /* scratch: their coordinates before smoothing */
    int32_t *chg;              /* triangles whose records the smoothing renewed */
    size_t cap_mask, cap_list, cap_old, nchg, cap_chg;
} af_state;

static inline const double *af_pt(const cvm__refiner *R, int32_t v)
{
    return R->T->xy + 2 * (size_t)v;
}

/* Grow *p (int32_t) to at least need elements, the new ones set to fill;
 * 0, or 1 on NOMEM. */
static inline int af_grow_fill(cvm__ctx *ctx, int32_t **p, size_t *cap, size_t need, int32_t fill)
{
    size_t k = *cap;
    if (need <= *cap)
        return 0;
    if (cvm__grow(ctx, (void **)p, cap, need, sizeof **p))
        return 1;
    for (; k < *cap; k++)
        (*p)[k] = fill;
    return 0;
}

/* ---- edge layers, per triangle slot (aflr_layers.c) ---- */

/* 1 when the layers stored for slot t belong to the triangle now in it. */
static inline int af_slot_valid(const af_state *A, const cvm__tri2 *T, int32_t t)
{
    return 3 * (size_t)t + 2 < A->cap_sv && cvm__tri2_slot_holds(T, t, A->sv + 3 * (size_t)t);
}

/* Layer of edge j of triangle t: from its segment when constrained, else
 * what slot t (or the triangle across) stored, else AF_INF. */
int32_t cvm__af_edge_layer(const cvm__refiner *R, int32_t t, int j);
/* Record the three edge layers of slot t and the quality q of its triangle.
 * CVM_OK or CVM_E_NOMEM. */
cvm_status cvm__af_store(af_state *A, cvm__refiner *R, int32_t t, const int32_t *l, int q);

/* ---- classification, front edges, the queue, placement (aflr_front.c) ---- */

/* Quality of triangle t (AF_OK, AF_BIG, AF_SKINNY), AF_BIG outside the domain. */
int cvm__af_quality_any(cvm__refiner *R, int32_t t);
/* cvm__af_quality_any, from slot t's record when it is valid: the vertices do not
 * move during the pass, so a triangle's quality never changes, and each
 * triangle is measured once, when made, instead of at every look. */
static inline int af_quality_cached(cvm__refiner *R, int32_t t)
{
    const af_state *A = R->aflr;
    if ((size_t)t < A->cap_sq && af_slot_valid(A, R->T, t))
        return A->sq[t];
    return cvm__af_quality_any(R, t);
}

/* Best front edge of bad triangle t of quality q: *j_out, *layer_out,
 * *key_out (the queue key); 0 when t has no front edge (aflr_front.c). */
int cvm__af_front_edge(cvm__refiner *R, int32_t t, int q, int *j_out, int32_t *layer_out,
                       double *key_out);
/* Queue domain triangle t when it is bad and has a front edge (into the band's
 * queue or, with interleaved smoothing, the waiting one); its quality into
 * *q_out. CVM_OK or CVM_E_NOMEM. */
cvm_status cvm__af_queue_triangle(cvm__refiner *R, int32_t t, int *q_out);
/* After vertex v was inserted for a front edge of layer base_layer (AF_INF:
 * a segment split): the layers of its spokes, the grid, the queue. */
cvm_status cvm__af_new_vertex(cvm__refiner *R, int32_t v, int32_t base_layer);
/* R->queue_star during the pass: a vertex inserted by a segment split. */
cvm_status cvm__af_queue_star(cvm__refiner *R, int32_t v);
/* The point for front edge j of bad triangle t into x; 0 when every
 * candidate lies too close to a vertex. */
int cvm__af_point(cvm__refiner *R, int32_t t, int j, double *x);

/* ---- interleaved smoothing (aflr_smooth.c) ---- */

/* The queue of the current group ran empty: smooth the group and move on to
 * the next (*more = 1) unless nothing is left (*more = 0). */
cvm_status cvm__af_next_group(cvm__refiner *R, int *more);

#endif
