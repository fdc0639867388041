/*
 * refine_internal.h - mesh refinement on the 2D kernel: the sizing handle,
 * the queue of bad triangles, segment encroachment and splitting, Delaunay
 * refinement (Ruppert 1995; Shewchuk 1997/2002, as in Triangle) and
 * frontal-Delaunay refinement (Rebay 1993: points on the bisectors of front
 * edges, grown from the boundary).
 *
 * The module works on a cvm__tri2 and plain parameters; it never sees the
 * cvm_mesh handle. Topological decisions (where a point lies, which triangles
 * its cavity holds) use the exact predicates of lib/geom through the kernel.
 * Quality decisions (is a triangle bad, is a segment encroached, where to put
 * a Steiner point) use ordinary floating point: they choose *which* valid mesh
 * results, never whether the mesh is valid.
 *
 * Determinism: queues are ordered by total keys whose ties are broken by
 * vertex ids, never by addresses; no hash table is iterated.
 */
#ifndef CVM_REFINE_INTERNAL_H
#define CVM_REFINE_INTERNAL_H

#include <stddef.h>
#include <stdint.h>
#include "common/common_internal.h"
#include "delaunay/delaunay_internal.h"

/* ---- sizing (sizing.c) ---- */

typedef struct cvm__point_source {
    double x, y, h, growth;
} cvm__point_source;

typedef struct cvm__line_source {
    double x0, y0, x1, y1, h, growth;
} cvm__line_source;

struct cvm_sizing {
    cvm__ctx ctx;
    int has_uniform;
    double uniform;
    cvm__point_source *pts;
    size_t npts, cap_pts;
    cvm__line_source *lines;
    size_t nlines, cap_lines;
    cvm_sizing_fn fn;
    void *fn_payload;
};

/* 1 when s is NULL or has no source (no size bound). */
int cvm__sizing_is_empty(const cvm_sizing *s);

/* Size at (x, y) into *h (+infinity without sources). A bad callback value
 * records an error naming the callback and the position on err and returns
 * CVM_E_INPUT_NONFINITE or CVM_E_ARGUMENT. */
cvm_status cvm__sizing_at(const cvm_sizing *s, double x, double y, double *h, cvm__ctx *err);

/* ---- bad-triangle queue (bad_queue.c) ---- */

/* An entry: the triangle slot and its vertices rotated so the smallest id is
 * first (which identifies the triangle whatever slot it occupies), a class
 * (lower first) and a key (lower first). */
typedef struct cvm__bad_entry {
    double key;
    int32_t cls;
    int32_t t;
    int32_t v[3];
} cvm__bad_entry;

typedef struct cvm__bad_queue {
    cvm__ctx *ctx;
    cvm__bad_entry *e;
    size_t n, cap;
} cvm__bad_queue;

void cvm__bq_init(cvm__bad_queue *q, cvm__ctx *ctx);
void cvm__bq_destroy(cvm__bad_queue *q);
void cvm__bq_clear(cvm__bad_queue *q);
/* Push triangle t of T with class cls and key; CVM_OK or CVM_E_NOMEM. */
cvm_status cvm__bq_push(cvm__bad_queue *q, const cvm__tri2 *T, int32_t t, int32_t cls, double key);
/* Pop the entry of least (cls, key, v0, v1, v2) into *out; 0 when empty. */
int cvm__bq_pop(cvm__bad_queue *q, cvm__bad_entry *out);
/* 1 when the entry still names a live triangle with the same vertices. */
int cvm__bq_valid(const cvm__tri2 *T, const cvm__bad_entry *e);

/* ---- the refiner ---- */

/* What a run is asked to do. */
typedef struct cvm__refine_params {
    int algo;                  /* CVM_ALGO_DELAUNAY or CVM_ALGO_FRONTAL */
    double min_angle_deg;      /* requested minimum angle; 0 = none */
    double max_area;           /* 0 = none */
    uint64_t max_steiner;      /* 0 = none */
    int lens;                  /* 1: diametral lens instead of circle */
    int march;                 /* 1: march segments with the sizing first */
    const cvm_sizing *sizing;  /* may be NULL */
    const int32_t *seg_ends;   /* 2 per segment id: the vertices ending the input segment */
    size_t nseg;               /* segment ids 0..nseg-1 */
    int swap;                  /* 1: swap edges towards degree 6 after refining */
    int smooth_sweeps;         /* sweeps of smart Laplacian smoothing after refining */
    int restore_delaunay;      /* 1: restore the constrained Delaunay property at the end */
} cvm__refine_params;

/* What a run did (see CVM_MEASURE_REFINE_* in cvmesh.h). */
typedef struct cvm__refine_report {
    size_t steiner;
    size_t unmet_angle;
    size_t unmet_size;
    size_t small_angle;
    double met_angle_deg;      /* smallest angle over non-exempt triangles */
} cvm__refine_report;

/* Results of trying to insert a free Steiner point. */
enum { CVM__RF_DONE = 0, CVM__RF_SPLIT = 1, CVM__RF_REJECT = 2 };

/* State shared by the refiner's files. */
typedef struct cvm__refiner {
    cvm__tri2 *T;
    cvm__ctx *ctx;
    const cvm__refine_params *p;
    int32_t *seg_ends;         /* 2 per segment id, hull segments appended */
    size_t nseg;               /* ids 0..nseg-1 (input, then hull) */
    double sin2_min;           /* sin^2 of the requested angle */
    double lens_cos2;          /* cos^2(2 x angle) for the lens test */
    double *vls;               /* size at each vertex (+inf: none) */
    int32_t *vseg;             /* per vertex: segment it was split onto, -2 input vertex on a
                                  segment, -1 free */
    size_t cap_vls, cap_vseg;
    /* queue the bad triangles around a new vertex (Delaunay or frontal rules) */
    cvm_status (*queue_star)(struct cvm__refiner *R, int32_t v);
    cvm__bad_queue q;
    int32_t *segq;             /* queue of subsegments to split: a, b, seg per entry */
    size_t segq_head, segq_n, cap_segq;
    int32_t *star;             /* scratch: triangles around a vertex */
    size_t cap_star;
    int32_t *cav;              /* scratch: cavity of a candidate point */
    size_t cap_cav;
    int32_t *enc;              /* scratch: encroached subsegments (a, b, seg) */
    size_t nenc, cap_enc;
    size_t steiner;
} cvm__refiner;

/* Refine T in place (see cvm_mesh_refine). Returns CVM_OK, CVM_E_NOMEM,
 * CVM_E_ARGUMENT / CVM_E_INPUT_NONFINITE (sizing callback), CVM_E_INTERNAL or
 * CVM_INCOMPLETE_*; the triangulation is valid on every return. */
cvm_status cvm__refine(cvm__tri2 *T, const cvm__refine_params *p, cvm__refine_report *rep);

/* Record a new vertex v (segment seg or -1) in the per-vertex arrays and count
 * it as a Steiner point. CVM_OK, CVM_E_NOMEM or a sizing error. */
cvm_status cvm__rf_new_vertex(cvm__refiner *R, int32_t v, int32_t seg);
/* Steiner budget, clock and cancellation before one more insertion. */
cvm_status cvm__rf_may_insert(cvm__refiner *R);
/* Triangles around vertex v into R->star; returns their number, or 0 on NOMEM. */
size_t cvm__rf_star(cvm__refiner *R, int32_t v);
/* Half-edge a->b: triangle *t_out with edge *j_out from a to b counter-clockwise.
 * Returns 0 when a-b is not an edge. */
int cvm__rf_find_edge(cvm__refiner *R, int32_t a, int32_t b, int32_t *t_out, int *j_out);

/* ---- encroachment (encroach.c) ---- */

/* 1 when p encroaches segment ab: inside its diametral circle, or lens. */
int cvm__rf_encroaches(const cvm__refiner *R, const double *a, const double *b, const double *p);
/* After inserting v: queue each subsegment in the star of v that v encroaches
 * or that is encroached by the apex of a triangle of the star. */
cvm_status cvm__rf_queue_encroached_star(cvm__refiner *R, int32_t v);
/* Queue every encroached subsegment of the mesh (start of a run). */
cvm_status cvm__rf_queue_encroached_all(cvm__refiner *R);
/* Subsegments on the cavity boundary of the point x, which lies in triangle
 * t0 (already added as vertex v but not inserted), that x encroaches: into
 * R->enc. CVM_OK or CVM_E_NOMEM. */
cvm_status cvm__rf_cavity_encroached(cvm__refiner *R, int32_t v, int32_t t0);

/* ---- segment splitting (split_segment.c) ---- */

/* Queue subsegment a-b of segment seg for splitting. */
cvm_status cvm__rf_segq_push(cvm__refiner *R, int32_t a, int32_t b, int32_t seg);
/* Split every queued subsegment (and those their splits encroach).
 * CVM_OK or a stop / error status. */
cvm_status cvm__rf_split_queued(cvm__refiner *R);
/* Split subsegment a-b now; *done_out = 1 if a vertex was added. */
cvm_status cvm__rf_split_segment(cvm__refiner *R, int32_t a, int32_t b, int32_t seg,
                                 int *done_out);
/* March every subsegment with the sizing (CVM_OPT_MARCH_SEGMENTS). */
cvm_status cvm__rf_march_segments(cvm__refiner *R);

/* ---- Delaunay refinement (delaunay_refine.c) ---- */

/* Quality of triangle t: *bad_out 0 (good), 1 (too big: key = -ratio),
 * 2 (bad shape: key = sin^2 of its smallest angle), 3 (bad shape but exempt:
 * a small input angle subtends it). size_factor scales the size test. */
int cvm__rf_classify(cvm__refiner *R, int32_t t, double *key_out);
/* Try to insert the free point x for bad triangle t: CVM__RF_DONE (inserted,
 * new triangles queued by the caller via *v_out), CVM__RF_SPLIT (x encroached
 * or was blocked by segments, which were split instead), CVM__RF_REJECT (x
 * cannot be used). Status in *s_out. */
int cvm__rf_insert_free(cvm__refiner *R, int32_t t, const double *x, int32_t *v_out,
                        cvm_status *s_out);
/* Queue the bad triangles around vertex v (Delaunay refinement classes). */
cvm_status cvm__rf_queue_star(cvm__refiner *R, int32_t v);
/* Run Delaunay refinement until no triangle is bad (queue rebuilt from all triangles). */
cvm_status cvm__rf_delaunay(cvm__refiner *R);

/* ---- frontal-Delaunay (frontal.c) ---- */

/* Run the frontal pass (then the caller runs cvm__rf_delaunay to clean up). */
cvm_status cvm__rf_frontal(cvm__refiner *R);

/* ---- post-processing (swap.c, smooth.c) ---- */

/* sin^2 of the smallest angle of triangle (p, q, r); 0 unless counter-clockwise. */
double cvm__rf_min_sin2(const double *p, const double *q, const double *r);
/* Sweeps of edge flips (triangle index order) towards the ideal vertex degree
 * (6 inside; round(boundary angle / 60 degrees) + 1 on the boundary): an
 * unconstrained edge between two domain triangles whose quadrilateral is
 * strictly convex (exact orient2d) is flipped when the sum of squared degree
 * deviations of its four vertices drops, both new triangles keep every angle
 * with sin^2 >= R->sin2_min and neither is too big for the size bounds
 * (R->vls, max_area). The result need not be Delaunay.
 * CVM_OK or CVM_E_NOMEM (the triangulation stays valid). */
cvm_status cvm__rf_swap_degree(const cvm__refiner *R, size_t *flips_out);
/* Lawson flips (exact in-circle) until every unconstrained edge between two
 * domain triangles is locally Delaunay. CVM_OK, or CVM_E_NOMEM when the edge
 * stack could not grow: the flips are then finished by allocation-free sweeps,
 * so the result is (constrained) Delaunay on every return. */
cvm_status cvm__rf_restore_delaunay(cvm__tri2 *T, size_t *flips_out);
/* Smart Laplacian smoothing: sweeps over vertices first..nv-1 in index order
 * (Steiner points only: input points never move); a vertex whose star is in
 * the domain with no constrained spoke (so never a vertex on a segment) moves
 * to the best of three points on the way to the centroid of its neighbours
 * (0.5, 1 and 1.5 times the step) when every star triangle stays strictly
 * counter-clockwise (exact orient2d), the star's regularity improves (fewer
 * obtuse angles, more angles in [55, 65] degrees, then mean ratio), no more
 * star triangles exceed the size bound (R->vls, max_area) and no angle drops
 * below min(the star's smallest angle, the requested angle). Floating point
 * decides only which valid mesh results. Breaks the Delaunay property.
 * CVM_OK or CVM_E_NOMEM (the triangulation stays valid). */
cvm_status cvm__rf_smooth(cvm__refiner *R, size_t first, int sweeps, size_t *moves_out);

#endif
