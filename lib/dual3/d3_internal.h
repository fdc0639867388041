/*
 * d3_internal.h - shared between the files of lib/dual3 (see dual3.h).
 */
#ifndef CVM_DUAL3_INTERNAL_H
#define CVM_DUAL3_INTERNAL_H

#include "dual3/dual3.h"

/* Bounds of one move's topology repair (d3_flip.c): flips, the tetrahedra of a
 * star, and what follows from them (queue, undo log, appended tetrahedra). */
#define CVM__D3_MAX_FLIPS 8
/* Per vertex and sweep: trials whose fixed star would be refused on its penalty or
 * angles that still get a flip repair when only local regularity failed. */
#define CVM__D3_SPECULATIVE 24
#define CVM__D3_MAX_STAR 1024
#define CVM__D3_QUEUE (4 * CVM__D3_MAX_STAR + 20 * CVM__D3_MAX_FLIPS)
#define CVM__D3_LOG (80 * CVM__D3_MAX_FLIPS + 80)

/* One undone write of a move: kind 0 nbr, 1 dead, 2 vt, 3 deg; idx; the old value. */
typedef struct cvm__d3_undo {
    int32_t idx, old;
    int kind;
} cvm__d3_undo;

typedef struct cvm__d3_work {
    cvm__d3_mesh W;  /* the working mesh: the caller's vertices and weights (updated in
                        place), the connectivity below */
    const cvm__d3_mesh *M; /* &W */
    const cvm__d3_params *p;
    /* the connectivity, cap tetrahedra: slots below ntet, dead ones marked */
    int32_t *tet, *nbr; /* 4 cap */
    uint8_t *cface;     /* 4 cap */
    double *attr;       /* cap, or NULL when the mesh has no region attributes */
    uint8_t *dead;      /* cap */
    uint32_t *mark;     /* cap: visit stamps */
    uint32_t stamp;
    size_t ntet, cap;
    int32_t *vt;     /* nv: one live tetrahedron of each vertex, or -1 */
    int32_t *deg;    /* nv: live tetrahedra at each vertex */
    int32_t *star;   /* CVM__D3_MAX_STAR: the star of the vertex being solved, increasing t */
    int32_t *star0;  /* CVM__D3_MAX_STAR: the star before a move with flips */
    size_t nstar, nstar0;
    int32_t *queue;  /* CVM__D3_QUEUE slots 4 t + f */
    cvm__d3_undo *log; /* CVM__D3_LOG */
    size_t nlog;
    int logging;     /* 1: writes go to the log (a move that may be undone) */
    int32_t *remap;  /* cap: compaction map */
    uint8_t *fixpos; /* nv: 1 when the vertex lies on a constrained face */
    uint8_t *out;    /* cap: 1 when the power vertex lies strictly outside (exact) */
    uint8_t *bnd;    /* cap: 1 when a face has no neighbour */
    double *lv;      /* nv: mean length of the vertex's edges (counted per tetrahedron) */
    uint8_t *slide;  /* nv: for a vertex on a constrained face, the axes it may move along */
    uint8_t *stuck;  /* nv: 1 when the last search from v failed and nothing near v moved since */
    size_t nout;     /* sum of out */
    size_t flips;    /* flips kept */
    size_t mflips;   /* flips of the last cvm__d3_restore() */
    size_t sweep;    /* the current sweep (keys the cuckoo streams) */
    int budget;      /* the compass search's evaluations per vertex this sweep */
    /* params.slide 2 (d3_slide.c): vertices sliding on the surface as it was */
    uint8_t *curved; /* nv: 1 when the vertex slides on its ring */
    double *tan;     /* 6 nv: the tangent basis of such a vertex */
    int32_t *rstart, *rface; /* its ring: the faces rface[rstart[v] .. rstart[v + 1]) */
    double *rxyz;    /* 9 per ring face: its corners when the run began */
} cvm__d3_work;

/* One nest of the cuckoo search: offsets u over the free degrees of freedom,
 * the point x = (x, y, z, w) they give, its fitness f. */
typedef struct cvm__d3_nest {
    double u[4], x[4], f;
} cvm__d3_nest;
#define CVM__D3_NESTS 40

/* The penalty of one tetrahedron (dual3.h); HUGE_VAL when it is flat or
 * inverted in floating point. dist_out (may be NULL): |centroid - power vertex|. */
double cvm__d3_tet_penalty(const double *const P[4], const double W[4], double margin,
                           double *dist_out);
/* The corners and weights of tetrahedron t of M with vertex v (if a corner) at x, wv. */
void cvm__d3_corners(const cvm__d3_mesh *M, size_t t, int32_t v, const double *x, double wv,
                     const double *P[4], double W[4]);
/* The summed penalty of v's star (K->star) with v at (x, wv); the sum is cut short
 * once it reaches stop (HUGE_VAL: the full sum). */
double cvm__d3_star_penalty(const cvm__d3_work *K, int32_t v, const double *x, double wv,
                            double stop);
/* The largest cosine of a dihedral angle of tetrahedron t with v at x (2 when flat). */
double cvm__d3_tet_max_cos(const cvm__d3_mesh *M, size_t t, int32_t v, const double *x);
/* The cosine of the smallest dihedral angle of v's star with v at x (2 when a
 * tetrahedron is flat). */
double cvm__d3_star_max_cos(const cvm__d3_work *K, int32_t v, const double *x);
/* The exact checks of dual3.h for v at (x, wv) over its star: -1 when a tetrahedron
 * is not positively oriented; 1 when oriented but a face became non-regular (with
 * flips also: a face failing before on a tie only now fails strictly); 2 when
 * regular but the non-compliant count grows; 0 when v may move there (counts 0: the
 * count is not checked). */
int cvm__d3_star_check(const cvm__d3_work *K, int32_t v, const double *x, double wv, int counts);
/* 1 when face f of tetrahedron t is locally regular or constrained (exact). */
int cvm__d3_face_regular(const cvm__d3_mesh *M, size_t t, int f);
/* 1 when face f of t is not locally regular with v at (x, wv) (exact; whichever side
 * has v as a corner decides, so the answer does not depend on the side). sos 1: ties
 * perturbed as cvm__d3_face_regular(); 0: a tie is regular (strict test). */
int cvm__d3_face_conflict_at(const cvm__d3_mesh *M, size_t t, int f, int32_t v, const double *x,
                             double wv, int sos);

/* Modified Cuckoo Search (d3_cuckoo.c) for v from cur = (x, y, z, w) over its free
 * coordinates (those the compass search uses) and its weight, about budget
 * evaluations of the fixed star's penalty (HUGE_VAL where a tetrahedron is flat or
 * inverted, or a dihedral cosine exceeds cfloor), the stream seeded by key. Fills
 * ns[0..n) (n returned, at most CVM__D3_NESTS; ns[0] is cur) best first: ns[i].x the
 * point, ns[i].f its fitness; order is scratch of CVM__D3_NESTS. No exact test. */
int cvm__d3_cuckoo(const cvm__d3_work *K, int32_t v, const double *cur, double cfloor,
                   int budget, uint64_t key, cvm__d3_nest *ns, int *order);

/* ---- sliding on the surface (d3_slide.c) ---- */
/* Find the vertices that slide on their ring (params.slide 2) and keep the rings. */
cvm_status cvm__d3_slide_init(cvm__ctx *ctx, cvm__d3_work *K, const cvm__d3_mesh *M);
void cvm__d3_slide_free(cvm__ctx *ctx, cvm__d3_work *K);
/* x (3) := the nearest point of v's ring. */
void cvm__d3_slide_project(const cvm__d3_work *K, int32_t v, double *x);

/* ---- mutable connectivity (d3_flip.c) ---- */
/* Allocate the arrays above for M (capacity for growth) and copy its tetrahedra. */
cvm_status cvm__d3_topo_init(cvm__ctx *ctx, cvm__d3_work *K, const cvm__d3_mesh *M);
void cvm__d3_topo_free(cvm__ctx *ctx, cvm__d3_work *K);
/* K->star = the live tetrahedra at v, increasing; 0, or -1 when there are more than
 * CVM__D3_MAX_STAR or they are not connected through faces at v. */
int cvm__d3_gather_star(cvm__d3_work *K, int32_t v);
/* Drop the dead slots (order kept): slot t moves to K->remap[t]. */
void cvm__d3_compact(cvm__d3_work *K);
/* With v just moved (its star in K->star, the move's start ntet0), flip until every
 * face around v and of the new tetrahedra is locally regular, or was not regular
 * before the move (v at x0, w0) and is unchanged; 1 on success, 0 when the bounded
 * flips do not get there (call cvm__d3_undo()). Logs every write. */
int cvm__d3_restore(cvm__d3_work *K, int32_t v, const double *x0, double w0, size_t ntet0);
/* Undo the logged writes and drop the slots from ntet0 on. */
void cvm__d3_undo_all(cvm__d3_work *K, size_t ntet0);
/* Flip every face that is not locally regular where a flip is possible and no new
 * tetrahedron has a dihedral cosine above max(cfloor, the largest of the tetrahedra
 * around the face) (cfloor >= 2: no such limit); bounded passes. Returns the flips made. */
size_t cvm__d3_regularise(cvm__d3_work *K, double cfloor);

#endif
