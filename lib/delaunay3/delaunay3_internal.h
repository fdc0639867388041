/*
 * delaunay3_internal.h - the 3D Delaunay / regular tetrahedralisation engine:
 * a flat tetrahedral store closed by a ghost vertex, BRIO + Hilbert insertion
 * order, visibility-walk location and Bowyer-Watson cavities decided by the
 * exact predicates of lib/geom (insphere_sos, power3d_sos).
 *
 * Techniques after Marot, Pellerin and Remacle, "One machine, one minute,
 * three billion tetrahedra" (IJNME 2019, HXT): 4 vertex ids and 4 neighbour
 * slots per tetrahedron in flat arrays, a neighbour slot encoded 4 * tet + face
 * (face f is opposite vertex f), every hull face closed by a ghost tetrahedron
 * whose vertex 3 is the ghost, slots of deleted tetrahedra reused, cavity
 * boundaries kept in a flat array. BRIO is Amenta, Choi and Rote (2003); the
 * Hilbert index is Skilling's transpose form (AIP Conf. Proc. 707, 2004).
 * The time goes to mispredicted branches and cache misses more than to
 * arithmetic: the cavity search (conflict3.h) and the walk (insert3.c) take no
 * branch on a geometric test, neighbours are prefetched as the cavity grows,
 * and tetrahedron and point records are 64-byte aligned.
 *
 * Orientation: a finite tetrahedron (a, b, c, d) has cvm__orient3d(a, b, c, d)
 * > 0. A ghost tetrahedron (a, b, c, G) has its hull face (a, b, c) oriented
 * so that a point q outside the hull beyond it has orient3d(a, b, c, q) > 0
 * (the ghost stands for a point at infinity on that side).
 *
 * Ties: every in-sphere / power decision is symbolically perturbed by INPUT
 * index (cvm__insphere_sos), so the result does not depend on the insertion
 * order: with distinct points the tetrahedralisation is unique, and
 * cvm__tet3_copy_tets() numbers it canonically.
 *
 * Parallel insertion (parallel3.c, T->threads > 1, Delaunay or regular): a
 * BRIO round of at least T->par_min points is cut into T->threads runs of
 * equal count along its Hilbert order; the Hilbert keys at the cuts split
 * space into partitions, and every vertex belongs to the partition of its
 * key. A thread owns the tetrahedra whose finite vertices all lie in its
 * partition (the ghost belongs to everyone) and inserts the points of its
 * partition touching only those: a walk or a cavity that meets a tetrahedron
 * it does not own gives the point up before anything is written, and the
 * point waits for the next pass. Tetrahedra across partitions stay as they
 * are; a new tetrahedron links to one by writing the neighbour word of the
 * shared face, which only the owner of the other side ever writes. Slots,
 * free lists and the workspace (a per-thread copy of this struct, sharing its
 * arrays) are handed out before the threads start, so nothing is allocated
 * while they run. The next pass moves the cuts (by half a run, then a
 * quarter, ...), as the points left wait near the old ones; what is left
 * after a few passes is inserted serially. Duplicate points are merged before
 * insertion, into the lowest input index (weighted builds do so with any thread
 * count: same coordinates and same weight).
 * Weighted: a point whose owned located tetrahedron does not conflict with it
 * is hidden (redundant); a vertex of a cavity on none of its boundary faces
 * vanishes, and since every tetrahedron around it was dug it lies in the
 * thread's partition, whose fates and stamps the thread alone writes.
 *
 * Why the output does not depend on the thread count: each insertion digs the
 * whole conflict cavity (a partial one is given up), so every step is a
 * Bowyer-Watson insertion into a Delaunay tetrahedralisation and the result
 * is the Delaunay tetrahedralisation of the points, unique under the
 * perturbation by input index; cvm__tet3_copy_tets() writes it in canonical
 * order. Weighted, it is the regular tetrahedralisation of the perturbed
 * weighted points, and its vertex set is unique too: a point with an empty
 * power cell at some step has one at every later step, so the points
 * reported redundant (hidden on insertion or vanished later) are exactly
 * those that are no vertex of the result, in any order. Duplicates are
 * resolved before any insertion, by coordinates (and weight) and input index
 * only; the lowest index of a group has the largest perturbed weight, so the
 * others would be hidden by it anyway. A thread reads and writes only what it owns, plus the
 * vertex words of cross-partition tetrahedra (which no one changes during a
 * pass) and their neighbour words facing its own tetrahedra, so even the
 * store's internal state is a function of the input and the thread count.
 *
 * Memory: every allocation goes through the context's allocator; an
 * allocation failure returns CVM_E_NOMEM and leaves a store that
 * cvm__tet3_free() releases. No allocation happens inside a parallel region.
 * Thread-safety: one store per call; the threads of a parallel build are its
 * own (OpenMP; without OpenMP the partitions run one after another). Pure C99.
 */
#ifndef CVM_DELAUNAY3_INTERNAL_H
#define CVM_DELAUNAY3_INTERNAL_H

#include <stddef.h>
#include <stdint.h>

#include "common/common_internal.h"

#define CVM__T3_GHOST INT32_C(-1) /* the vertex at infinity (always vertex 3 of its tet) */
#define CVM__T3_DEAD INT32_C(-2)  /* tt[8 t] of a free slot */
/* The neighbour across face s & 3 of tetrahedron s >> 2, as an lvalue. */
#define CVM__T3_TN(T, s) ((T)->tt[(size_t)(s) + ((size_t)(s) & ~(size_t)3) + 4])

/* Fate of an input point after cvm__tet3_build(). */
enum {
    CVM__T3_PENDING = 0,   /* not inserted (build stopped early) */
    CVM__T3_VERTEX = 1,    /* a vertex of the tetrahedralisation */
    CVM__T3_DUPLICATE = 2, /* same coordinates (and weight) as a vertex: merged into it */
    CVM__T3_REDUNDANT = 3  /* weighted only: its power cell is empty, it is in no tetrahedron */
};

/* One face of the cavity boundary: the new tetrahedron's vertices (the
 * inserted point at position f), the slot of the outside neighbour and the
 * new tetrahedron made on it. */
typedef struct cvm__t3_bface {
    int32_t v[4];
    int32_t f;
    int32_t out;
    int32_t tet;
    uint8_t lid[4]; /* edge table: local ids of the three face vertices, in the cyclic order of
                     * cvm__tet3_link_around (tet3_store.c) */
} cvm__t3_bface;

/* A point, with the scratch word of the edge table next to its coordinates
 * (read anyway by the predicates, so it is in cache when needed). */
typedef struct cvm__t3_point {
    double x[3];
    uint32_t loc; /* (stamp << 7) | local id in the current cavity boundary */
    uint32_t pad;
} cvm__t3_point;

/* Entry of the edge table that pairs the new tetrahedra around the point. */
typedef struct cvm__t3_hent {
    uint64_t key;
    int32_t slot;
    uint32_t stamp;
} cvm__t3_hent;

typedef struct cvm__tet3 {
    cvm__ctx *ctx;
    size_t np;        /* input points */
    cvm__t3_point *pt; /* np: the points in insertion order (internal ids), 64-byte aligned */
    void *pt_block;   /* the allocation holding pt (cvm__tet3_alloc_points) */
    double *w;        /* np weights in insertion order; NULL for Delaunay */
    int32_t *orig;    /* internal id -> input index (the SoS index) */
    int32_t *merged;  /* internal id -> internal id of the vertex a duplicate merged into, or -1 */
    uint8_t *fate;    /* internal id -> CVM__T3_* */
    int32_t *outid;   /* internal id of a vertex -> input index naming it in the output:
                       * the lowest of it and the duplicates merged into it */

    int32_t *tt;      /* 8 per slot (one half cache line; tt is 64-byte aligned, so no slot
                       * straddles two lines): 4 vertex ids (internal, ghost last; DEAD in the
                       * first when free), then 4 neighbour slots 4 * tet + face */
    void *tt_block;   /* the allocation holding tt */
    uint8_t *tmark;   /* per slot: 1 in the current cavity, 2 tested outside it, 3 left out of
                       * it (constrained insertion), else 0 */
    uint8_t *cface;   /* per slot, or NULL: bit f set when face f is constrained (a loaded
                       * constrained mesh, cvm__tet3_load()) */
    double *sattr;    /* per slot, or NULL: the region attribute of a loaded mesh */
    size_t nslot;     /* slots in use or free, below cap */
    size_t cap;
    int32_t *freeslot;
    size_t nfree, freecap;

    /* insertion workspace, reused from point to point */
    int32_t *stack;
    size_t stackcap;
    int32_t *dead;
    size_t ndead, deadcap;
    int32_t *excl;    /* constrained insertion: tetrahedra left out of the cavity (tmark 3) */
    size_t nexcl, exclcap;
    cvm__t3_bface *bf;
    size_t nbf, bfcap;
    cvm__t3_hent *hash;
    size_t hashcap;   /* a power of two */
    uint32_t stamp;
    uint32_t lstamp;
    int32_t *etab;    /* CVM__T3_ETAB^2 table of directed edges (local ids) -> face slot */
    uint32_t *vseen;  /* weighted only: per internal vertex, stamp of the last cavity it was in */
    uint32_t *vkeep;  /* ... and of the last cavity boundary it was on */
    uint32_t vstamp;  /* the stamp of the current cavity for vseen / vkeep */

    int small_int;    /* unweighted and every coordinate an integer in [-256, 256]: the plain
                       * floating-point insphere / orient3d are exact (geom_internal.h) */
    int32_t last;     /* a finite tetrahedron made by the last insertion: next walk's start */
    uint64_t walk;    /* xorshift state of the walk's face order (deterministic) */

    /* settings, kept by cvm__tet3_free(): threads of a build (0: OpenMP's default; 1:
     * serial; the output does not depend on it), and the smallest BRIO round run in
     * parallel (tests lower it) */
    int threads;
    size_t par_min;
    /* parallel builds only (else NULL): per internal id its insertion key (BRIO round
     * << 30 | Hilbert index, ascending), and a tetrahedron made when it was inserted
     * (a walk's start; checked before use, the slot may have been reused) */
    uint64_t *key;
    int32_t *vtet;

    /* report of the last build, in input indices */
    size_t n_dup;          /* points merged into an identical vertex */
    int64_t dup_first[2];  /* (kept, merged) pair with the smallest merged index, or -1 */
    size_t n_redundant;    /* weighted: points whose power cell vanished */
    int64_t redundant_first; /* the smallest such index, or -1 */
    size_t n_finite;       /* finite tetrahedra */
    size_t n_big_cavities; /* cavities with more than 63 boundary vertices (hash-linked) */
    size_t n_par_done;     /* points settled (inserted, or found hidden) by parallel passes; how
                            * many does depend on the thread count, the output does not */
} cvm__tet3;

/* An empty store on ctx (not owned). */
void cvm__tet3_init(cvm__tet3 *T, cvm__ctx *ctx);
/* Release everything; the store is empty and reusable afterwards. */
void cvm__tet3_free(cvm__tet3 *T);

/*
 * Delaunay (w == NULL) or regular (weights w, power distance |x - p|^2 - w)
 * tetrahedralisation of the n points xyz[3 n] (copied). seed fixes the BRIO
 * rounds; the result (as cvm__tet3_copy_tets() writes it) does not depend on
 * it. Points with the same coordinates (and, weighted, the same weight) are
 * merged into the one of lowest index and counted in n_dup; weighted points
 * whose power cell is empty are left out and counted in n_redundant. With
 * T->threads other than 1, a build (weighted or not) of at least T->par_min points
 * inserts in parallel (see the top of this file); everything it reports and
 * cvm__tet3_copy_tets() writes is the same as with one thread.
 * @return CVM_OK
 *         CVM_E_INPUT_NONFINITE  a coordinate or weight is NaN or infinite (message names the point)
 *         CVM_E_INPUT_DEGENERATE fewer than 4 distinct points, or all collinear or coplanar,
 *                                or a nonzero coordinate (square root of |weight|) more than
 *                                2^100 below the largest: beyond the exact predicates' range
 *         CVM_E_TOO_LARGE        n above CVM__T3_MAX_POINTS
 *         CVM_E_NOMEM            (the store stays freeable)
 */
#define CVM__T3_ETAB 64
#define CVM__T3_MAX_POINTS ((size_t)60000000)
#define CVM__T3_PAR_MIN ((size_t)1 << 13) /* default T->par_min */
#define CVM__T3_HBITS 30                  /* Hilbert index bits of a key */
cvm_status cvm__tet3_build(cvm__tet3 *T, const double *xyz, const double *w, size_t n,
                           uint64_t seed);

/* Input index of each point's fate: fate_out[i] = CVM__T3_*, and for a
 * duplicate into_out[i] = input index of the vertex it merged into (else -1).
 * Either output may be NULL. */
void cvm__tet3_point_fates(const cvm__tet3 *T, uint8_t *fate_out, int32_t *into_out);

/* Write the T->n_finite finite tetrahedra as 4 input indices each into dst, in
 * the canonical order: each tetrahedron is turned by an even permutation
 * (orientation kept) so that its smallest index comes first and the smallest
 * of the other three second; the list is then sorted lexicographically.
 * Identical input gives identical bytes whatever the seed or insertion order.
 * With T->threads other than 1 and 8 T->par_min slots or more, the
 * scatter and the bucket sorts run on that many threads (the same bytes).
 * @return CVM_OK or CVM_E_NOMEM (temporaries: n / 2048 + 2048 counters and a buffer of
 *         the tetrahedra whose first index shares its high bits with the most others,
 *         about 6.75 * 2048 for uniform input; each times the threads when parallel). */
cvm_status cvm__tet3_copy_tets(cvm__tet3 *T, int32_t *dst);
/* The canonical turn of one tetrahedron used by cvm__tet3_copy_tets(). */
void cvm__tet3_canonical_turn(int32_t *t);

/* Re-verify the store with exact predicates: live slots, symmetric adjacency
 * whose shared faces match, every finite tetrahedron positively oriented,
 * every interior face locally Delaunay (regular) by insphere_sos (power3d_sos),
 * the hull convex, every vertex in a tetrahedron. Returns CVM_OK or
 * CVM_E_INTERNAL with a message naming the first offending tetrahedron/face. */
cvm_status cvm__tet3_check(cvm__tet3 *T);

/* Store internals shared by the engine's files. */
/* T->pt for cap points, zeroed, 64-byte aligned (a point record never straddles two
 * cache lines); CVM_OK or CVM_E_NOMEM. cvm__tet3_free() releases it. */
cvm_status cvm__tet3_alloc_points(cvm__tet3 *T, size_t cap);
cvm_status cvm__tet3_reserve(cvm__tet3 *T, size_t need_new);
int32_t cvm__tet3_take_slot(cvm__tet3 *T);
void cvm__tet3_release_slot(cvm__tet3 *T, int32_t t);
/* Pair the faces of the new tetrahedra bf[i].tet (i < nbf) around their
 * common apex at position bf[i].f: face k != f of one meets the face of
 * another along the edge of the two vertices at neither k nor f. The hash
 * holds at least 4 nbf entries (cvm__tet3_reserve_hash). */
void cvm__tet3_link_around(cvm__tet3 *T);
/* Replace a dug cavity (dead[], ndead) by the tetrahedra joining the apex to
 * its boundary faces bf[] (slots of the cavity first, then free ones, then
 * fresh ones; cvm__tet3_reserve and cvm__tet3_reserve_hash made room), link
 * them to the outside and around the apex, clear the marks, free the dead
 * slots left over. T->last becomes a finite new tetrahedron. */
void cvm__tet3_fill_around(cvm__tet3 *T);
cvm_status cvm__tet3_reserve_hash(cvm__tet3 *T, size_t nfaces);
/* BRIO rounds, Hilbert order inside each: order[0..n) a permutation of 0..n-1.
 * key, when not NULL, receives the n sorted keys (round << CVM__T3_HBITS | Hilbert index). */
cvm_status cvm__tet3_brio_order(cvm__ctx *ctx, const double *xyz, size_t n, uint64_t seed,
                                int32_t *order);
cvm_status cvm__tet3_brio_keys(cvm__ctx *ctx, const double *xyz, size_t n, uint64_t seed,
                               int32_t *order, uint64_t *key);
/* The thread count a build runs with (T->threads resolved, at most 64). */
int cvm__tet3_build_threads(const cvm__tet3 *T);
/* Parallel and weighted builds: mark every point with the coordinates (and, weighted,
 * the weight) of an earlier one (internal order) a duplicate of the first of its group
 * (CVM_OK or CVM_E_NOMEM). */
cvm_status cvm__tet3_merge_duplicates(cvm__tet3 *T);
/* Parallel builds: insert every pending point after the first tetrahedron, round by
 * round (parallel3.c). CVM_OK or CVM_E_NOMEM. */
cvm_status cvm__tet3_insert_rounds(cvm__tet3 *T);
/* Insert internal point p into a store that already has a first tetrahedron. */
cvm_status cvm__tet3_insert(cvm__tet3 *T, int32_t p);
/* Weighted: before the dug cavity of p (dead[], bf[]) is filled, mark REDUNDANT
 * every vertex of it on none of its boundary faces (its power cell goes to p).
 * Touches vseen / vkeep of the cavity's vertices only; restarts the stamps (all
 * np of them) when T->vstamp wraps, which a parallel pass rules out beforehand. */
void cvm__tet3_mark_vanished(cvm__tet3 *T, int32_t p);

/*
 * Load an existing mesh for point insertion (cvm__tet3_insert_point()): nv
 * vertices xyz (weights w, or NULL), ntet positively oriented tetrahedra tet
 * with face adjacency nbr (4 u + g, or -1 on the boundary), room for cap >= nv
 * points. Internal ids are the vertex ids, and so are the symbolic-perturbation
 * indices. Every boundary face is closed by a ghost. cons (4 per tetrahedron,
 * nonzero = constrained face), or NULL for an unconstrained Delaunay / regular
 * mesh; boundary faces of a constrained mesh are constrained. attr: one per
 * tetrahedron, or NULL. CVM_OK or CVM_E_NOMEM (no message; the store stays
 * freeable).
 */
cvm_status cvm__tet3_load(cvm__tet3 *T, const double *xyz, const double *w, size_t nv, size_t cap,
                          const int32_t *tet, size_t ntet, const int32_t *nbr, const uint8_t *cons,
                          const double *attr);

/* The finite tetrahedra of the store. */
size_t cvm__tet3_count_finite(const cvm__tet3 *T);
/* The finite tetrahedra into tet (4 each, in slot order, turned as
 * cvm__tet3_copy_tets() turns them) with their attributes into attr (when not
 * NULL; 0 without), the points into xyz (3 * T->np) and the weights into w
 * (when both exist); a vertex v >= nv_old is renamed fin[v - nv_old]. */
void cvm__tet3_export(const cvm__tet3 *T, size_t nv_old, const int32_t *fin, int32_t *tet,
                      double *attr, double *xyz, double *w);

/* What became of a point given to cvm__tet3_insert_point(). */
typedef enum cvm__t3_ins {
    CVM__T3_INS_DONE = 0,     /* inserted as vertex T->np - 1 */
    CVM__T3_INS_OUTSIDE,      /* strictly outside the hull, or outside the constrained domain */
    CVM__T3_INS_DUPLICATE,    /* on an existing vertex (*other) */
    CVM__T3_INS_TOO_CLOSE,    /* closer than min_dist to vertex *other of its cavity */
    CVM__T3_INS_ON_CONSTRAINT,/* on a constrained face (or edge): no valid cavity */
    CVM__T3_INS_REDUNDANT,    /* weighted: its power cell would be empty */
    CVM__T3_INS_HIDES         /* weighted: it would leave vertex *other without a power cell */
} cvm__t3_ins;

/*
 * Insert the point x (weight 0 in a weighted store) into a loaded store
 * (cvm__tet3_load(), T->np < cap). The cavity is the set of tetrahedra in
 * conflict with x (in-sphere / power test with symbolic perturbation) grown
 * from the one containing it, never across a constrained face; in a
 * constrained store a tetrahedron whose boundary face x does not see strictly
 * from inside is left out again, until the cavity is star-shaped from x. The
 * min_dist test: squared distances to the cavity's vertices in doubles, x is
 * refused when one is below min_dist^2. sos: the point's symbolic-perturbation
 * index (above every vertex's; only the order of the indices matters). *res
 * says what happened; on DONE the point is vertex T->np - 1. CVM_OK, or
 * CVM_E_NOMEM (store unchanged).
 */
cvm_status cvm__tet3_insert_point(cvm__tet3 *T, const double *x, int32_t sos, double min_dist,
                                  cvm__t3_ins *res, int32_t *other);

#endif
