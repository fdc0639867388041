/*
 * refine_internal.h - mesh refinement on the 2D kernel: the queue of bad
 * triangles, segment encroachment and splitting, Delaunay
 * refinement (Ruppert 1995; Shewchuk 1997/2002, as in Triangle) and
 * frontal-Delaunay refinement (Rebay 1993: points on the bisectors of front
 * edges, grown from the boundary) and advancing-front local reconnection
 * (Marcum 1995) inside the Delaunay kernel.
 *
 * The module works on a cvm__tri2 and plain parameters; it never sees the
 * cvm_mesh handle. Topological decisions (where a point lies, which triangles
 * its cavity holds) use the exact predicates of lib/geom through the kernel.
 * Quality decisions (is a triangle bad, is a segment encroached, where to put
 * a Steiner point) use ordinary floating point: they choose *which* valid mesh
 * results, never whether the mesh is valid.
 *
 * Determinism: queues are ordered by keys and then push order (which follows
 * from the triangulation, never from addresses); no hash table is iterated.
 */
#ifndef CVM_REFINE_INTERNAL_H
#define CVM_REFINE_INTERNAL_H

#include <stddef.h>
#include <stdint.h>
#include "common/common_internal.h"
#include "delaunay/delaunay_internal.h"
#include "sizing/sizing_internal.h"

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

/* Classes 0..CVM__BQ_NCLASS-1 (a class outside is clamped into the range). */
#define CVM__BQ_NCLASS 2

/* Entries per block of a bucket's chain. */
#define CVM__BQ_BLOCK 32
struct cvm__bq_block;

/*
 * Bucket queue (as Triangle's): an entry goes into bucket
 * cvm__bq_bucket(cls, key) and entries leave in the order (bucket, push
 * order): lower class first; inside a class, lower quantised key first; inside
 * a bucket, first in first out. The key is quantised to its sign, binary
 * exponent and leading 4 significand bits, so a bucket spans a relative key
 * width of 1/31 to 1/16 (2^e (1 + j/16) to 2^e (1 + (j+1)/16)); keys that
 * differ by more than a factor 1 + 1/16 always leave in key order. Order is a
 * function of the pushes alone (never of addresses), so runs are reproducible.
 * Stale entries are not removed on push; the caller skips them on pop with
 * cvm__bq_valid, or pops with cvm__bq_pop_valid (the pool also drops them in
 * bulk when most are stale).
 */
typedef struct cvm__bad_queue {
    cvm__ctx *ctx;
    struct cvm__bq_block *blk; /* block pool */
    size_t used, cap;          /* blocks ever used, capacity */
    int32_t free;              /* free list of blocks, -1 if none */
    size_t n;                  /* entries queued */
    int32_t *bk;               /* per bucket: head block, read position, tail block,
                                  write position (valid while its bit is set) */
    uint64_t *bits;            /* non-empty buckets: one bit each, then one per word */
    uint64_t l2;               /* one bit per non-zero summary word */
} cvm__bad_queue;

void cvm__bq_init(cvm__bad_queue *q, cvm__ctx *ctx);
void cvm__bq_destroy(cvm__bad_queue *q);
void cvm__bq_clear(cvm__bad_queue *q);
/* The bucket of (cls, key): lower buckets leave first. */
size_t cvm__bq_bucket(int32_t cls, double key);
/* Push triangle t of T with class cls and key; CVM_OK or CVM_E_NOMEM. */
cvm_status cvm__bq_push(cvm__bad_queue *q, const cvm__tri2 *T, int32_t t, int32_t cls, double key);
/* Pop the first entry of the least non-empty bucket into *out; 0 when empty. */
int cvm__bq_pop(cvm__bad_queue *q, cvm__bad_entry *out);
/* The same, skipping (and dropping) entries that are no longer valid in T;
 * fetches the triangles of the next entries into the cache meanwhile, and
 * their vertices' entries of vdata (NULL, or one double per vertex of T that
 * the caller reads for each entry). */
int cvm__bq_pop_valid(cvm__bad_queue *q, const cvm__tri2 *T, const double *vdata,
                      cvm__bad_entry *out);
/* 1 when the entry still names a live triangle with the same vertices. */
int cvm__bq_valid(const cvm__tri2 *T, const cvm__bad_entry *e);

/* ---- the refiner ---- */

/* What a run is asked to do. */
typedef struct cvm__refine_params {
    int algo;                  /* CVM_ALGO_DELAUNAY, CVM_ALGO_FRONTAL or CVM_ALGO_AFLR */
    double min_angle_deg;      /* requested minimum angle; 0 = none */
    double max_area;           /* 0 = none */
    uint64_t max_steiner;      /* 0 = none */
    int lens;                  /* 1: diametral lens instead of circle */
    int march;                 /* 1: march segments with the sizing first */
    double march_grade;        /* > 0: the march grades pieces away from short pieces at
                                  subsegment ends at this rate (CVM__MARCH_GRADE);
                                  0: each subsegment is marched on its own */
    const cvm_sizing *sizing;  /* may be NULL */
    const int32_t *seg_ends;   /* 2 per segment id: the vertices ending the input segment;
                                  -1 for an end that CVM_OPT_KEEP_SEGMENT_VERTICES = 0
                                  removed (an inner vertex of a re-discretised chain) */
    size_t nseg;               /* segment ids 0..nseg-1 */
    int swap;                  /* 1: swap edges towards degree 6 after refining */
    int smooth_sweeps;         /* sweeps of smoothing after refining */
    int relax_sweeps;          /* relaxation sweeps before them (method 0, 2, 3) */
    int smooth_method;         /* 0 smart Laplacian, 1 max-min (Freitag), 2 both in turn,
                                  3 Laplacian then guarded max-min */
    int restore_delaunay;      /* 1: restore the constrained Delaunay property at the end */
    const double *region_area; /* NULL, or per region index the maximum area (<= 0: none);
                                  then T->ta holds each triangle's region index (-1: none) */
    size_t nregion;
    const unsigned char *seg_front; /* AFLR: nseg flags, 1 when the segment starts a front;
                                       NULL: every segment (hull segments too) */
    int aflr_smooth_layers;    /* AFLR: > 0 smooths the vertices of every N completed layers
                                  during the pass (CVM_OPT_AFLR_SMOOTH_LAYERS); 0 off */
} cvm__refine_params;

/* What a run did (see CVM_MEASURE_REFINE_* in cvmesh.h). */
typedef struct cvm__refine_report {
    size_t steiner;
    size_t unmet_angle;
    size_t unmet_size;
    size_t small_angle;
    double met_angle_deg;      /* smallest angle over non-exempt triangles */
    double *unmet;             /* 3 per triangle left unmet: centroid x, y, reason bits
                                  (CVM_UNMET_*), allocated on the run's context */
    size_t n_unmet;
    double *cell_layer;        /* AFLR: layer index per triangle slot (T->nt of the result,
                                  -1 where no front reached), allocated through the
                                  triangulation's ctx and owned by the caller; else NULL */
} cvm__refine_report;

/* A factor within 1e-9 of 1 that the frontal and advancing-front refiners
 * apply to the distance of a new point: deterministic in the vertex count nv,
 * it keeps the points off an exact lattice (lattice points are cocircular in
 * many fours, which sends the insertion's in-circle tests to their slow exact
 * stages). nv is spread by Knuth's multiplicative hash (2^32 / golden ratio)
 * over CVM__RF_JITTER_STEPS steps in [1 - CVM__RF_JITTER_REL, 1 + ...). */
#define CVM__RF_JITTER_HASH 2654435761u
#define CVM__RF_JITTER_STEPS 2048u
#define CVM__RF_JITTER_REL 1e-9
static inline double cvm__rf_lattice_jitter(size_t nv)
{
    uint32_t h = (uint32_t)nv * CVM__RF_JITTER_HASH;
    return 1 + CVM__RF_JITTER_REL *
                   ((double)(h % CVM__RF_JITTER_STEPS) / (CVM__RF_JITTER_STEPS / 2) - 1.0);
}

/* Largest area allowed for triangle t: CVM_OPT_MAX_AREA and its region's
 * maximum area, the smaller of those set; 0 = none. */
#define cvm__rf_max_area(R, t) cvm__rf_max_area_((R)->p, (R)->T, (t))
static inline double cvm__rf_max_area_(const cvm__refine_params *p, const cvm__tri2 *T, int32_t t)
{
    double a = p->max_area;
    if (p->region_area && T->ta) {
        double r = T->ta[t];
        if (r >= 0 && r < (double)p->nregion) {
            double ra = p->region_area[(size_t)r];
            if (ra > 0 && (a <= 0 || ra < a))
                a = ra;
        }
    }
    return a;
}

/* Results of trying to insert a free Steiner point. */
enum { CVM__RF_DONE = 0, CVM__RF_SPLIT = 1, CVM__RF_REJECT = 2 };

/* State shared by the refiner's files. */
typedef struct cvm__refiner {
    cvm__tri2 *T;
    cvm__ctx *ctx;
    const cvm__refine_params *p;
    int32_t *seg_ends;         /* 2 per segment id (-1 as in cvm__refine_params), hull segments appended */
    size_t nseg;               /* ids 0..nseg-1 (input, then hull) */
    double sin2_min;           /* sin^2 of the requested angle */
    double size2;              /* size test: circumradius^2 <= size2 x (mean size)^2 (1, or
                                  CVM__FRONTAL_ACCEPT2 after the frontal and AFLR passes) */
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
    size_t ncav, cap_cav;      /* (ncav: as cvm__rf_cavity_encroached left it) */
    int32_t *enc;              /* scratch: encroached subsegments (a, b, seg) */
    size_t nenc, cap_enc;
    size_t steiner;
    void *aflr;                /* AFLR state (aflr_internal.h) while an AFLR run lasts, else NULL */
    struct cvm__fr_rec *fr_rec; /* frontal.c: quality record per triangle slot while a
                                  frontal pass lasts, else NULL */
    size_t cap_fr_rec;
} cvm__refiner;

/* Refine T in place (see cvm_mesh_refine). Returns CVM_OK, CVM_E_NOMEM,
 * CVM_E_ARGUMENT / CVM_E_INPUT_NONFINITE (sizing callback), CVM_E_INTERNAL or
 * CVM_INCOMPLETE_*; the triangulation is valid on every return. */
cvm_status cvm__refine(cvm__tri2 *T, const cvm__refine_params *p, cvm__refine_report *rep);

/* ---- shared refiner state (refiner_state.c) ---- */

/* Make room in the per-vertex arrays (vls, vseg) for n vertices. CVM_OK or
 * CVM_E_NOMEM (no message). */
cvm_status cvm__rf_reserve_vertices(cvm__refiner *R, size_t n);
/* Record a new vertex v (segment seg or -1) in the per-vertex arrays and count
 * it as a Steiner point. CVM_OK, CVM_E_NOMEM or a sizing error. */
cvm_status cvm__rf_new_vertex(cvm__refiner *R, int32_t v, int32_t seg);
/* Steiner budget, clock and cancellation before one more insertion. */
cvm_status cvm__rf_may_insert(cvm__refiner *R);
/* Triangles around vertex v into R->star; returns their number, or 0 on NOMEM. */
size_t cvm__rf_star(cvm__refiner *R, int32_t v);
/* Queue subsegment a-b of segment seg for splitting (R->segq). CVM_OK or
 * CVM_E_NOMEM (message set). */
cvm_status cvm__rf_segq_push(cvm__refiner *R, int32_t a, int32_t b, int32_t seg);
/* Vertex c lies strictly between a and b along a-b and within 2^-40 (M + L)
 * of its line (M the largest coordinate of a and b, L their distance): the
 * tolerance of a segment's chain (cvm_mesh_triangulate()). A floating-point
 * test with a stated tolerance: it chooses a chain, the kernel's exact tests
 * decide whether the mesh change it asks for is valid. */
int cvm__rf_on_chain(const double *a, const double *b, const double *c);

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
 * R->enc; the cavity's triangles into R->cav[0..R->ncav). CVM_OK or
 * CVM_E_NOMEM. */
cvm_status cvm__rf_cavity_encroached(cvm__refiner *R, int32_t v, int32_t t0);

/* ---- segment splitting (split_segment.c) ---- */

/* Split every queued subsegment (and those their splits encroach).
 * CVM_OK or a stop / error status. */
cvm_status cvm__rf_split_queued(cvm__refiner *R);
/* Split subsegment a-b now; *done_out = 1 if a vertex was added, or if the
 * split was refused and the chain was routed through a vertex instead
 * (cvm__rf_route_through). */
cvm_status cvm__rf_split_segment(cvm__refiner *R, int32_t a, int32_t b, int32_t seg,
                                 int *done_out);
/* Subsegment a-b of segment seg is edge j of domain triangle t. When the apex
 * c of t or of the domain triangle across lies strictly between a and b within
 * the chain tolerance of a-b and of the input segment (cvm__rf_on_chain), that
 * triangle is a wedge of a vanishing angle (typically between a-b and a
 * segment ending at c) that no rounded split point of either can enter. The
 * chain then passes through c, as it does through a rounded crossing: a-b is
 * flipped to c-d (d the other apex; exact orientation tests decide that the
 * quadrilateral is convex), a-c and c-b become pieces of seg (an edge another
 * segment holds keeps it), the flat triangle joins d's side (its flags and
 * region) and the stars are made constrained Delaunay again. Every routing
 * adds a vertex to a chain, so it happens finitely often. With requeue, the
 * stars of the four vertices are queued again (bad triangles, encroached
 * subsegments). *done_out: 1 when the chain was routed. CVM_OK or
 * CVM_E_NOMEM / a queueing status. */
cvm_status cvm__rf_route_through(cvm__refiner *R, int32_t t, int j, int32_t seg, int requeue,
                                 int *done_out);
/* March every subsegment with the sizing (CVM_OPT_MARCH_SEGMENTS). */
cvm_status cvm__rf_march_segments(cvm__refiner *R);
/* The grading rate g of the march (h_b = min(h, l(e) + g d(x, e)), see
 * split_segment.c); consecutive pieces then differ by about exp(g). */
/* Default smoothing of each refiner (CVM_OPT_SMOOTH_SWEEPS and
 * CVM_OPT_RELAX_SWEEPS at -1). Frontal leaves rougher seams where fronts meet,
 * so it gets more smart sweeps; fewer relaxation sweeps pay for part of them.
 * Figures in docs/design/refiners.md. */
#define CVM__FRONTAL_SMOOTH_SWEEPS 4
/* Frontal accepts a triangle whose circumradius is at most sqrt(this) times
 * the local size (Rebay's "small enough"): a right isosceles triangle with legs
 * of the local size sits at the limit (0.707), the equilateral triangle of
 * that size has 0.577. After the frontal and the AFLR passes the clean-ups,
 * swaps and smoothing keep that bound too (refiner.c: R->size2): without it
 * the Delaunay-restoring flips after smoothing left a few triangles up to
 * 0.78 x the size (frontal) and AFLR's edge rule (< 1.5 x size) up to 0.81 x. */
#define CVM__FRONTAL_ACCEPT2 0.5
#define CVM__FRONTAL_RELAX_SWEEPS 3
#define CVM__AFLR_SMOOTH_SWEEPS 3
#define CVM__AFLR_RELAX_SWEEPS 5

#ifndef CVM__MARCH_GRADE
#define CVM__MARCH_GRADE 0.3
#endif

/* ---- Delaunay refinement (delaunay_refine.c) ---- */

/* Quality of triangle t: *bad_out 0 (good), 1 (too big: key = -ratio),
 * 2 (bad shape: key = sin^2 of its smallest angle), 3 (bad shape but exempt:
 * a small input angle subtends it). size_factor scales the size test. */
int cvm__rf_classify(cvm__refiner *R, int32_t t, double *key_out);
/* Try to insert x, a point off every segment, for bad triangle t:
 * CVM__RF_DONE (inserted, new triangles queued by the caller via *v_out),
 * CVM__RF_SPLIT (x encroached or was blocked by segments, which were split
 * instead), CVM__RF_REJECT (x cannot be used). Status in *s_out. */
int cvm__rf_try_interior_point(cvm__refiner *R, int32_t t, const double *x, int32_t *v_out,
                               cvm_status *s_out);
/* Queue the bad triangles around vertex v (Delaunay refinement classes). */
cvm_status cvm__rf_queue_star(cvm__refiner *R, int32_t v);
/* Run Delaunay refinement until no triangle is bad (queue rebuilt from all triangles). */
cvm_status cvm__rf_delaunay(cvm__refiner *R);

/* ---- frontal-Delaunay (frontal.c) ---- */

/* Run the frontal pass (then the caller runs cvm__rf_delaunay to clean up). */
cvm_status cvm__rf_frontal(cvm__refiner *R);

/* ---- advancing-front local reconnection (aflr*.c, proximity_grid.c) ---- */

/* Run the AFLR pass (the caller then runs cvm__rf_delaunay to clean up). Its
 * state (edge layers) stays in R->aflr for cvm__rf_aflr_cell_layers() until
 * cvm__rf_aflr_free(). CVM_OK, CVM_E_NOMEM, a sizing error or a stop status. */
cvm_status cvm__rf_aflr(cvm__refiner *R);
/* Layer index of every triangle slot of the final mesh into a fresh array
 * *out (T->nt entries, through ctx): max + 0.1 x min of its edges' layers,
 * edges created after the AFLR pass (clean-up, swaps) taking one more than
 * the lowest layer at their ends, passed on along such edges; -1 where no
 * front reached. CVM_OK or
 * CVM_E_NOMEM. */
cvm_status cvm__rf_aflr_cell_layers(cvm__refiner *R, double **out);
/* Free R->aflr (NULL is fine). */
void cvm__rf_aflr_free(cvm__refiner *R);

/* A uniform grid that stores vertices (proximity_grid.c): per-cell linked
 * lists that grow and move with the mesh (cvm__vertex_grid_add / _move), for
 * "any vertex closer than r" queries during advancing-front refinement.
 * Unlike cvm__cell_grid it owns its storage. */
typedef struct cvm__vertex_grid {
    cvm__ctx *ctx;
    double x0, y0, inv;        /* origin and 1 / cell size */
    int32_t nx, ny;
    int32_t *head;             /* nx*ny: first vertex of each cell, -1 */
    int32_t *next;             /* per vertex: next vertex of its cell, -1 */
    size_t cap_next;
} cvm__vertex_grid;

/* Grid over the box [x0, x1] x [y0, y1] with cells of about size cs (coarser
 * when that would need more than max_cells cells). CVM_OK or CVM_E_NOMEM. */
cvm_status cvm__vertex_grid_init(cvm__vertex_grid *g, cvm__ctx *ctx, double x0, double y0, double x1,
                           double y1, double cs, size_t max_cells);
void cvm__vertex_grid_destroy(cvm__vertex_grid *g);
/* Add vertex v at p (points outside the box go to the nearest cell). CVM_OK or CVM_E_NOMEM. */
cvm_status cvm__vertex_grid_add(cvm__vertex_grid *g, int32_t v, const double *p);
/* Vertex v of the grid, added at old, now lies at p: moved to p's cell. */
void cvm__vertex_grid_move(cvm__vertex_grid *g, int32_t v, const double *old, const double *p);
/* 1 when some vertex of the grid lies strictly closer than r to x (xy: all coordinates). */
int cvm__vertex_grid_any_within(const cvm__vertex_grid *g, const double *xy, const double *x, double r);

/* ---- post-processing (swap.c, smooth.c) ---- */

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
 * (Steiner points only: input points never move), only those v with only[v]
 * != 0 when only is not NULL (nv bytes); a vertex whose star is in
 * the domain with no constrained spoke (so never a vertex on a segment) moves
 * to the best of its candidates: 0.5, 1 and 1.5 times the step towards the
 * centroid of its neighbours and towards the ODT point, and, from the second
 * smart sweep on, the equilateral apexes of the star's outer edges, points
 * between them and a pattern search around the best (smooth.c,
 * SM_PATTERN_ITERS), when every star triangle stays strictly
 * counter-clockwise (candidates screened in floating point, the chosen one
 * checked with exact orient2d), the star's regularity improves (fewer
 * obtuse angles, more angles in [55, 65] degrees, then mean ratio), no more
 * star triangles exceed the size bound (R->vls, max_area) and no angle drops
 * below min(the star's smallest angle, the requested angle). Floating point
 * decides only which valid mesh results. Breaks the Delaunay property.
 * CVM_OK or CVM_E_NOMEM (the triangulation stays valid). */
cvm_status cvm__rf_smooth(cvm__refiner *R, size_t first, const uint8_t *only, int relax, int sweeps,
                         size_t *moves_out);
/* Max-min smoothing (Freitag and Ollivier's active-set method): the same
 * vertices (first, only), order and sweep rule as cvm__rf_smooth; each visited vertex
 * maximises the smallest sine of the angles of its star (= the sine of the
 * star's smallest angle): the active functions are those within 1e-6 of the
 * minimum, the search direction is the smallest-norm point of the convex
 * hull of their gradients (none: v is already max-min optimal), the first
 * step is where an inactive function meets them to first order (at most a
 * quarter of the shortest spoke), halved until the minimum grows by more
 * than 1e-12, every star triangle stays strictly counter-clockwise (exact
 * orient2d) and no more star triangles exceed the size bound; up to 12
 * steps, stopping when the gain falls below 1e-6 of the minimum. So the
 * smallest angle of a moved vertex's star strictly grows with each move.
 * guard = 1: only vertices whose star has an angle below 40 degrees move,
 * and only when the star keeps its number of obtuse angles minus angles in
 * [55, 65] degrees (as cvm__rf_smooth counts them) or lowers it.
 * Breaks the Delaunay property. CVM_OK or CVM_E_NOMEM (the triangulation
 * stays valid). */
cvm_status cvm__rf_smooth_maxmin(cvm__refiner *R, size_t first, const uint8_t *only, int sweeps,
                                 int guard, size_t *moves_out);

#endif
