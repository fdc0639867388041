/*
 * delaunay_internal.h - the 2D triangulation kernel: a triangulation of the
 * convex hull kept in compact arrays, closed by ghost triangles that share the
 * vertex at infinity (CVM__GHOST), with Bowyer-Watson insertion, segment
 * recovery (constrained Delaunay) and domain carving.
 *
 * Layout. Triangle t has vertices tv[3t..3t+2], counter-clockwise. Edge j of t
 * is the edge opposite vertex j, i.e. (tv[3t+(j+1)%3], tv[3t+(j+2)%3]).
 * tn[3t+j] = 3u+k says that edge j of t is edge k of triangle u. A ghost
 * triangle has tv[3t+0] == CVM__GHOST... no: the ghost vertex may sit at any
 * position; use cvm__tri2_is_ghost(). Dead (freed) triangles carry
 * CVM__TF_DEAD and are chained through tn[3t] into the free list.
 *
 * Constrained edges: when te != NULL, te[3t+j] is the index of the input
 * segment edge j of t lies on (>= 0), or -1. Both sides of an edge carry the
 * same value. Triangles outside the domain (exterior, holes) stay in the
 * structure with CVM__TF_OUT, so insertion is uniform; outputs skip them.
 *
 * Weights: when w != NULL, w[v] is the power weight of vertex v and every
 * in-circle decision becomes the power test (regular triangulation).
 *
 * Determinism: every decision depends only on coordinates, weights and
 * vertex indices (symbolic perturbation by index), never on addresses.
 */
#ifndef CVM_DELAUNAY_INTERNAL_H
#define CVM_DELAUNAY_INTERNAL_H

#include <stddef.h>
#include <stdint.h>
#include "common/common_internal.h"

#define CVM__GHOST (-1)

enum {
    CVM__TF_DEAD = 1,   /* slot is on the free list */
    CVM__TF_OUT = 2,    /* outside the domain (exterior or hole) */
    CVM__TF_MARK = 4,   /* scratch: in the current cavity / visited */
    CVM__TF_MARK2 = 8   /* scratch */
};

typedef struct cvm__tri2 {
    cvm__ctx *ctx;
    /* vertices */
    double *xy;        /* 2 per vertex */
    int32_t *vtri;     /* a live triangle incident to each vertex, or -1 */
    double *w;         /* NULL, or a weight per vertex */
    size_t nv, cap_v;   /* w, when not NULL, has cap_v entries too */
    /* triangles */
    int32_t *tv;       /* 3 per triangle */
    int32_t *tn;       /* 3 per triangle */
    uint8_t *tf;       /* flags per triangle */
    int32_t *te;       /* NULL, or 3 per triangle: input segment of each edge, -1 */
    double *ta;        /* NULL, or a regional attribute per triangle (inherited on insertion) */
    size_t nt, cap_t;  /* slots in use (live + dead), capacity */
    int32_t free_head; /* first dead slot, -1 if none */
    size_t n_dead;
    int32_t last;      /* start of the next walk */
    int32_t seg_keep_below; /* > 0: an edge already on a segment of id below this keeps that id
                             * when a segment of id at or above it is recovered over it (the
                             * temporary constraints of a rebuilt mesh file); 0: the later wins */
    /* scratch for cavities */
    int32_t *stack; size_t cap_stack;
    int32_t *cav;   size_t cap_cav;   /* triangles of the cavity */
    int32_t *bnd;   size_t cap_bnd;   /* boundary edges of the cavity, CVM__BND_STRIDE ints each */
    double *bta;    size_t cap_bta;   /* attribute of the triangle behind each boundary edge */
} cvm__tri2;

static inline int cvm__tri2_is_ghost(const cvm__tri2 *T, int32_t t)
{
    const int32_t *v = T->tv + 3 * (size_t)t;
    return v[0] == CVM__GHOST || v[1] == CVM__GHOST || v[2] == CVM__GHOST;
}

static inline int cvm__tri2_is_live(const cvm__tri2 *T, int32_t t)
{
    return !(T->tf[t] & CVM__TF_DEAD);
}

/* The live triangles around vertex v, counter-clockwise from vtri[v] (ghosts
 * included), into out[0..cap-1]; returns how many there are (possibly more
 * than cap: then only the first cap were written), 0 for an unused vertex. */
size_t cvm__tri2_star(const cvm__tri2 *T, int32_t v, int32_t *out, size_t cap);

/* Half-edge a->b: the live triangle *t_out (ghosts included) that has b after
 * a counter-clockwise, and *j_out the index of that edge (the corner opposite
 * it). Returns 0 when a-b is not an edge. */
int cvm__tri2_find_edge(const cvm__tri2 *T, int32_t a, int32_t b, int32_t *t_out, int *j_out);

/* A real (non-ghost) live triangle inside the domain. */
static inline int cvm__tri2_in_domain(const cvm__tri2 *T, int32_t t)
{
    return !(T->tf[t] & (CVM__TF_DEAD | CVM__TF_OUT)) && !cvm__tri2_is_ghost(T, t);
}

static inline int cvm__tri2_edge_seg(const cvm__tri2 *T, int32_t t, int j)
{
    return T->te ? T->te[3 * (size_t)t + j] : -1;
}

/* Corner (0, 1 or 2) of vertex v in triangle t; v must be a corner of t. */
static inline int cvm__tri2_corner(const cvm__tri2 *T, int32_t t, int32_t v)
{
    const int32_t *tv = T->tv + 3 * (size_t)t;
    return tv[0] == v ? 0 : tv[1] == v ? 1 : 2;
}

/* 1 when slot t holds the vertices v[0], v[1], v[2] in that order: a record a
 * refiner kept for the slot, written with those vertices, still describes the
 * triangle in it (slots are reused as the kernel flips and inserts). */
static inline int cvm__tri2_slot_holds(const cvm__tri2 *T, int32_t t, const int32_t *v)
{
    const int32_t *tv = T->tv + 3 * (size_t)t;
    return tv[0] == v[0] && tv[1] == v[1] && tv[2] == v[2];
}

/* One step of the walk around corner v of t (from T->vtri[v] back to it):
 * the triangle across t's edge opposite the corner after v. */
static inline int32_t cvm__tri2_around(const cvm__tri2 *T, int32_t t, int32_t v)
{
    return T->tn[3 * (size_t)t + (size_t)(cvm__tri2_corner(T, t, v) + 1) % 3] / 3;
}

void cvm__tri2_init(cvm__tri2 *T, cvm__ctx *ctx);
void cvm__tri2_destroy(cvm__tri2 *T);
/* Drop every vertex and triangle, keep the capacity. */
void cvm__tri2_clear(cvm__tri2 *T);

/* Make room for need vertices: CVM_OK, CVM_E_NOMEM or CVM_E_TOO_LARGE. */
cvm_status cvm__tri2_reserve_vertices(cvm__tri2 *T, size_t need);

/* Append a vertex (not yet inserted into the triangulation). Returns CVM_OK
 * or CVM_E_NOMEM / CVM_E_TOO_LARGE. *id_out receives its index. */
cvm_status cvm__tri2_add_vertex(cvm__tri2 *T, const double *p, int32_t *id_out);

/* Build the Delaunay triangulation of all vertices 0..nv-1 added so far,
 * inserted in a biased randomised (BRIO) Hilbert order drawn from seed.
 * dup_of (nv entries, caller's) receives for each vertex -1, or the vertex it
 * duplicates exactly (a duplicate is not inserted and has vtri -1).
 * Returns CVM_OK; CVM_E_INPUT_DEGENERATE (fewer than 3 distinct points, or all
 * collinear: message says so); CVM_E_NOMEM; CVM_INCOMPLETE_* from the ticker
 * (the triangulation is then cleared of triangles). */
cvm_status cvm__tri2_build(cvm__tri2 *T, uint64_t seed, int32_t *dup_of);

/* Results of locating a point. */
typedef enum cvm__loc {
    CVM__LOC_INSIDE = 0,   /* strictly inside triangle *t_out */
    CVM__LOC_EDGE = 1,     /* on the interior of edge *j_out of *t_out */
    CVM__LOC_VERTEX = 2,   /* on vertex tv[3*t+j] (j = *j_out) */
    CVM__LOC_OUTSIDE = 3   /* outside the convex hull: *t_out is a ghost triangle whose
                              hull edge sees p */
} cvm__loc;

/* Walk from triangle start (or T->last when start < 0) to p. */
cvm__loc cvm__tri2_locate(cvm__tri2 *T, const double *p, int32_t start, int32_t *t_out,
                          int *j_out);

/* Outcome of cvm__tri2_insert_vertex(). */
typedef enum cvm__ins {
    CVM__INS_DONE = 0,      /* inserted */
    CVM__INS_DUPLICATE = 1, /* coincides with vertex *other_out; not inserted */
    CVM__INS_OUTSIDE = 2,   /* outside the hull or the domain (with CVM__INSF_DOMAIN_ONLY) */
    CVM__INS_TOO_CLOSE = 3, /* closer than min_dist to vertex *other_out */
    CVM__INS_REDUNDANT = 4, /* weights set: its power cell would be empty; not inserted */
    CVM__INS_OFF_EDGE = 5   /* computed on an edge but rounded so far off it that it cannot
                               split it (cvm__tri2_split_edge); not inserted */
} cvm__ins;

enum {
    CVM__INSF_DOMAIN_ONLY = 1 /* reject points outside the hull or in CVM__TF_OUT triangles */
};

/* Insert existing vertex v (added with cvm__tri2_add_vertex) by Bowyer-Watson.
 * The cavity grows from the triangle containing v across non-constrained
 * edges only. If v lies exactly on a constrained edge, that edge is split and
 * both halves keep its segment index. hint: a triangle near v, or -1.
 * min_dist > 0 rejects v when a vertex that would become its neighbour is
 * closer than min_dist (in an unconstrained Delaunay triangulation the nearest
 * vertex is always such a neighbour).
 * Returns CVM_OK (see *res_out) or CVM_E_NOMEM (nothing changed). */
cvm_status cvm__tri2_insert_vertex(cvm__tri2 *T, int32_t v, int32_t hint, int flags,
                                   double min_dist, cvm__ins *res_out, int32_t *other_out);

/* Insert existing vertex v (added with cvm__tri2_add_vertex, no weights)
 * into the cavity cav[0..ncav) the caller found: the triangles, connected
 * across non-constrained edges and free of CVM__TF_MARK, whose circumcircle
 * holds v (exact in-circle test), one of them containing v strictly off every
 * constrained edge - the same set cvm__tri2_insert_vertex would grow, so a
 * refiner that has searched the cavity (for encroached segments) does not
 * search it twice. Returns CVM_OK or CVM_E_NOMEM (nothing changed). */
cvm_status cvm__tri2_insert_in_cavity(cvm__tri2 *T, int32_t v, const int32_t *cav, size_t ncav);

/* Insert vertex v, which the caller computed to lie on constrained edge j of
 * triangle t (possibly inexactly, e.g. a segment intersection): the edge is
 * split at v whatever the rounding, its halves keep the segment index.
 * *res_out: CVM__INS_DONE, or CVM__INS_OFF_EDGE when the rounding put v where
 * it cannot see the whole cavity (a tiny edge beside other tiny features;
 * nothing changed). Returns CVM_OK or CVM_E_NOMEM (nothing changed). */
cvm_status cvm__tri2_split_edge(cvm__tri2 *T, int32_t v, int32_t t, int j, cvm__ins *res_out);

/* Remove duplicate vertices (dup_of[v] >= 0) from the vertex arrays,
 * renumbering the rest in order; map_out (nv entries) receives old -> new id
 * (a duplicate maps to the new id of the vertex it duplicates). */
void cvm__tri2_compact(cvm__tri2 *T, const int32_t *dup_of, int32_t *map_out);

/* Reorder and rotate the slots of T: slot[k] (k < nfile, distinct live
 * slots) moves to slot k, rotated so that its vertex at position rot[k]
 * comes first; the other live slots follow in their order; dead slots are
 * dropped (the free list is emptied). Neighbour links, constraints,
 * attributes and vtri follow. CVM_OK or CVM_E_NOMEM (T unchanged). */
cvm_status cvm__tri2_reorder(cvm__tri2 *T, const int32_t *slot, const uint8_t *rot, size_t nfile);
/* 1 when every live real (non-ghost) triangle of T is strictly counter-clockwise (exact orient2d). */
int cvm__tri2_all_ccw(const cvm__tri2 *T);

/* Allocate ta if needed (all 0). */
cvm_status cvm__tri2_enable_attributes(cvm__tri2 *T);

/* Set ta = value on every non-OUT real triangle reachable from seed without
 * crossing a constrained edge. */
cvm_status cvm__tri2_flood_attribute(cvm__tri2 *T, int32_t seed, double value);

/* Make the segment a-b (vertex ids) a union of constrained edges carrying
 * segment index seg: edges are recovered by removing crossed triangles and
 * re-triangulating both sides (constrained Delaunay); a vertex lying exactly
 * on a-b splits it. If a-b crosses an already constrained edge of segment s2:
 * with split = 1 a vertex is added at the intersection (both segments split);
 * with split = 0 returns CVM_E_INPUT_INTERSECTING naming seg and s2.
 * Returns CVM_OK, CVM_E_INPUT_INTERSECTING, CVM_E_NOMEM. */
cvm_status cvm__tri2_insert_segment(cvm__tri2 *T, int32_t a, int32_t b, int32_t seg, int split,
                                    int32_t *other_seg_out);

/* Mark CVM__TF_OUT every triangle reachable without crossing a constrained
 * edge from each seed triangle (seeds: -1 entries ignored), plus all ghost
 * triangles when exterior = 1 (carving from the hull). */
cvm_status cvm__tri2_flood_out(cvm__tri2 *T, const int32_t *seeds, size_t nseeds, int exterior);

/* Carve one of many holes in time proportional to what it removes: mark
 * CVM__TF_OUT every triangle reachable from seed without crossing a
 * constrained edge, like cvm__tri2_flood_out(T, &seed, 1, 0), but leave
 * CVM__TF_MARK2 on the visited triangles and stop at triangles that carry it:
 * those were flooded by an earlier call, and reachability is symmetric, so
 * their whole region is OUT already. *visited_out receives the number of
 * triangles visited, *removed_out how many of them were in the domain before.
 * After the last call (and after an error) call cvm__tri2_clear_mark2().
 * Returns CVM_OK or CVM_E_NOMEM. */
cvm_status cvm__tri2_flood_out_more(cvm__tri2 *T, int32_t seed, size_t *visited_out,
                                    size_t *removed_out);

/* Clear the scratch flag CVM__TF_MARK2 on every triangle. */
void cvm__tri2_clear_mark2(cvm__tri2 *T);

/* Allocate te if needed (all -1). */
cvm_status cvm__tri2_enable_constraints(cvm__tri2 *T);

/* Exact in-circle (or power) test of vertex p against live real triangle t:
 * +1 conflict, -1 not, with symbolic perturbation by index. */
int cvm__tri2_conflict(const cvm__tri2 *T, int32_t t, int32_t p);

/* Restore the regular property (Delaunay without weights) by Lawson flips:
 * every non-constrained edge between two live real triangles of the same
 * domain flag and regional attribute whose quad is strictly convex is flipped
 * while it fails the exact power test (cvm__tri2_conflict). Terminates (each
 * flip lowers the lifted surface). An illegal edge whose quad is not convex
 * is left: its reflex corner is a vertex the regular triangulation would drop
 * (cvm__tri2_count_unregular counts them). *nflips_out (may be NULL) receives
 * the number of flips. CVM_OK or CVM_E_NOMEM (nothing changed). */
cvm_status cvm__tri2_make_regular(cvm__tri2 *T, size_t *nflips_out);
/* The same, and *ndomain_out (may be NULL) receives how many of the flips
 * were inside the domain (the rest are in its exterior or holes). */
cvm_status cvm__tri2_make_regular_count(cvm__tri2 *T, size_t *nflips_out, size_t *ndomain_out);

/* Number of vertices whose power cell is empty as far as the triangulation
 * shows: the blocking corner of each illegal, unflippable edge (see
 * cvm__tri2_make_regular), plus, with weights, vertices without a triangle
 * (dropped by insertion). mark: nv bytes of caller's scratch, 1 on return for
 * the blocking corners. */
size_t cvm__tri2_count_unregular(const cvm__tri2 *T, uint8_t *mark);

/* Verify the structure and (constrained) Delaunay property with exact
 * predicates; on failure sets a message naming the failed check and returns
 * CVM_E_INTERNAL. */
cvm_status cvm__tri2_check(cvm__tri2 *T);

/* ---- a planar straight-line graph to its constrained triangulation (pslg_build.c) ---- */

/* The input of cvm__cdt_build(), borrowed for the call: points with their
 * markers and attributes, segments (point indices, checked by the caller to
 * be in range) with their markers, hole points, regions and the options that
 * decide the result. */
typedef struct cvm__cdt_input {
    const double *xy;      /* 2 per point */
    size_t np;
    const int32_t *pmark;  /* np, or NULL: markers 0 */
    const double *pattr;   /* np * nattr, or NULL when nattr = 0 */
    size_t nattr;
    const int32_t *seg;    /* 2 per segment, 0-based point indices */
    size_t nseg;
    const int32_t *smark;  /* nseg, or NULL: every segment has marker 1 */
    const double *holes;   /* 2 per hole point */
    size_t nholes;
    const double *regions; /* 4 per region: x, y, attribute, max area */
    size_t nregions;
    uint64_t seed;         /* insertion order (CVM_OPT_SEED) */
    int reject_duplicates; /* a repeated point is an error, not merged */
    int split;             /* crossing segments are split at the crossing, not an error */
    int keep_hull;         /* segments do not carve the exterior away */
} cvm__cdt_input;

/* What cvm__cdt_build() makes besides the triangulation; the arrays are
 * allocated through the triangulation's ctx and owned by the caller, who
 * frees them also after an error. vmark and vattr are grown in place (they
 * may hold an earlier allocation of capacity cap_vmark, cap_vattr). */
typedef struct cvm__cdt_out {
    int32_t *input_map; /* np: input point -> vertex (a duplicate: its first occurrence's) */
    size_t n_dup;       /* input points merged into an earlier one */
    int32_t *vmark;     /* marker per vertex */
    double *vattr;      /* nattr per vertex, or NULL when nattr = 0 */
    size_t cap_vmark, cap_vattr;
} cvm__cdt_out;

/* An error of cvm__cdt_build() or cvm__cdt_carve() caused by one input item:
 * returned without a message, for the caller to name the items in its terms. */
typedef enum cvm__cdt_fault_kind {
    CVM__CDT_FAULT_NONE = 0,
    CVM__CDT_FAULT_RANGE,          /* point item: coordinate axis is nonzero and more than
                                      2^180 times smaller than big (CVM_E_INPUT_DEGENERATE) */
    CVM__CDT_FAULT_DUPLICATE,      /* point item lies at point other (CVM_E_INPUT_DUPLICATE) */
    CVM__CDT_FAULT_ZERO_LENGTH,    /* segment item has coinciding ends (CVM_E_INPUT_DEGENERATE) */
    CVM__CDT_FAULT_CROSSING,       /* segment item crosses segment other
                                      (CVM_E_INPUT_INTERSECTING) */
    CVM__CDT_FAULT_HOLE_OUTSIDE,   /* hole item outside the hull (CVM_E_INPUT_OUTSIDE) */
    CVM__CDT_FAULT_HOLE_ALL,       /* hole item removed the whole domain (CVM_E_INPUT_NOT_CLOSED) */
    CVM__CDT_FAULT_REGION_OUTSIDE  /* region item outside the domain (CVM_E_INPUT_OUTSIDE) */
} cvm__cdt_fault_kind;

typedef struct cvm__cdt_fault {
    cvm__cdt_fault_kind kind;
    size_t item, other; /* 0-based indices into the input's points, segments, holes, regions */
    int axis;           /* CVM__CDT_FAULT_RANGE: 0 x, 1 y */
    double big;         /* CVM__CDT_FAULT_RANGE: the largest absolute coordinate */
} cvm__cdt_fault;

/* Triangulate in into T (empty, its ctx the allocator and run control): the
 * Delaunay triangulation of the distinct points, the segments recovered as
 * constrained edges, the exterior (unless keep_hull or there are no
 * segments) and the holes carved, the regional attributes flooded; markers
 * and attributes of every vertex (first occurrences win; a vertex created on
 * a segment takes the segment's marker and the attributes interpolated
 * between its ends; a vertex of marker 0 on a segment takes the segment's
 * marker); then every segment is checked to be a chain of constrained edges
 * (cvm__cdt_check_chains). Returns CVM_OK; an input error with *fault set and
 * no message; CVM_E_INPUT_NOT_CLOSED, CVM_E_TOO_LARGE, CVM_E_NOMEM,
 * CVM_E_INTERNAL, CVM_INCOMPLETE_* (time limit, cancelled) and the errors of
 * cvm__tri2_build() with their message. After an error T and out hold a
 * partial result, to be dropped. */
cvm_status cvm__cdt_build(cvm__tri2 *T, const cvm__cdt_input *in, cvm__cdt_out *out,
                          cvm__cdt_fault *fault);

/* The carving step of cvm__cdt_build() alone, on a triangulation whose
 * segments are recovered: exterior, holes, regions of in (points, segments
 * and markers are not read, except nseg). Errors as cvm__cdt_build(). */
cvm_status cvm__cdt_carve(cvm__tri2 *T, const cvm__cdt_input *in, cvm__cdt_fault *fault);

/* Every input segment seg[2k], seg[2k+1] (point indices, mapped to vertices
 * by input_map; a segment with an end mapped to -1 is skipped) is joined end
 * to end by constrained edges through vertices within a rounding tolerance
 * of it. CVM_OK, CVM_E_INTERNAL (message names the segment), CVM_E_NOMEM. */
cvm_status cvm__cdt_check_chains(cvm__tri2 *T, const int32_t *seg, size_t nseg,
                                 const int32_t *input_map);

/* Marker of segment seg: smark[seg], 1 when smark is NULL; 0 for seg < 0 or
 * seg >= nseg (a convex-hull edge). */
int32_t cvm__cdt_segment_marker(const int32_t *smark, size_t nseg, int32_t seg);

/* Marker and attributes of a point p on segment seg of in: the segment's
 * marker into *mark, and into attr (in->nattr values) the attributes of its
 * ends interpolated by the projection of p, clamped to the segment; for seg
 * outside the segments only *mark (0) is written. */
void cvm__cdt_segment_point(const cvm__cdt_input *in, const double *p, int32_t seg,
                            int32_t *mark, double *attr);

#endif
