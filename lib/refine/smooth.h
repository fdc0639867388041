/* smooth.h - the star evaluation shared by the smoothing passes of lib/refine (smooth_star.c):
 * a vertex's star, its ring of neighbours, the regularity count of a candidate position, and the
 * marks that choose which vertices a sweep visits. The passes are smooth.c (smart Laplacian and
 * relaxation) and smooth_maxmin.c (Freitag-Ollivier max-min). */
#ifndef CVM_REFINE_SMOOTH_H
#define CVM_REFINE_SMOOTH_H

#include "refine_internal.h"

/* Weight of an obtuse angle against an angle in [55, 65] degrees in the
 * regularity count: high enough that the extra candidates never trade obtuse
 * triangles for regular angles (docs/design/refiners.md). */
#define SM_OBTUSE_WEIGHT 16

/* The star of a visited vertex, gathered once per visit: ring vertex k is the
 * second corner of star triangle k, whose third corner is ring vertex k + 1
 * (mod n, cvm__sm_star walks counter-clockwise); per triangle the squared length
 * of its outer edge, 4 x its size squared (HUGE_VAL: no size) and twice its
 * area bound (0: none). */
typedef struct cvm__sm_ring {
    size_t n, cap;
    double *a;   /* 2 per ring vertex */
    double *lab; /* per triangle */
    double *ls4;  /* 4 x size2 x size^2 */
    double *amax2;
    double size2; /* the refiner's size2 */
} cvm__sm_ring;

/* Star of v into *star (triangles, counter-clockwise); returns the count, or 0
 * when v may not move: a star triangle outside the domain or a constrained
 * spoke edge. *err is set on NOMEM. */
size_t cvm__sm_star(const cvm__tri2 *T, int32_t v, int32_t **star, size_t *cap, int *err);
/* The status of a smoothing stopped by the time limit or the progress
 * callback (cvm__tick, polled per vertex visit), with its message: every move
 * made keeps the mesh valid, so it stops where it is. */
cvm_status cvm__sm_stopped(cvm__ctx *ctx, cvm_status s);

void cvm__sm_ring_free(cvm__ctx *ctx, cvm__sm_ring *r);

/* Fill r from the star of v; returns 0 on NOMEM. */
int cvm__sm_ring_build(const cvm__refiner *R, int32_t v, const int32_t *star, size_t n,
                       cvm__sm_ring *r);

/* Regularity of the star of v (gathered in r) with v at p: *bad (lower is
 * better) = SM_OBTUSE_WEIGHT x obtuse angles - angles in [55, 65] degrees + 1e-3 x the sum
 * of (1 - mean ratio); *q = smallest sin^2; *big = triangles above the size
 * bound (circumradius above the mean size, or the area bound). Returns 0 when
 * a triangle is not strictly counter-clockwise (exact orient2d), or as soon
 * as *bad is sure to end >= cut (HUGE_VAL: the full count).
 * A candidate (qmin >= 0) is also rejected (0) as soon as a triangle has an
 * angle whose sin^2 is below qmin or more than bigmax triangles exceed the
 * size bound; *q is then not computed. Orientation is screened in floating
 * point here (a candidate whose doubled area is not positive is rejected);
 * a move is made only after cvm__sm_ring_exact. */
int cvm__sm_ring_eval(const cvm__sm_ring *r, const double *p, double cut, double qmin, int bigmax,
                      double *bad, double *q, int *big);

/* 1 when every star triangle of r is strictly counter-clockwise with the
 * vertex at p (exact orient2d): cvm__sm_ring_eval screens candidates in floating
 * point, a move is made only after this test. */
int cvm__sm_ring_exact(const cvm__sm_ring *r, const double *p);

/* 1 when every angle of the triangle with squared sides lpa = |pa|^2, lpb =
 * |pb|^2, lab = |ab|^2 is in [55, 65] degrees (the test of cvm__sm_ring_eval:
 * cos^2 of each angle between cos^2 65 and cos^2 55, and no obtuse one). */
int cvm__sm_sides_regular(double lpa, double lpb, double lab);

double cvm__sm_d2(const double *a, const double *b);

/* 1 when every angle of domain triangle t is in [55, 65] degrees. */
int cvm__sm_perfect(const cvm__tri2 *T, int32_t t);

/* 1 when every triangle of star[0..n-1] is perfect (cvm__sm_perfect). */
int cvm__sm_all_perfect(const cvm__tri2 *T, const int32_t *star, size_t n);

/* Vertex v moved: its star's vertices are revisited in the next sweep, and
 * those after v in this one. */
void cvm__sm_moved(const cvm__tri2 *T, size_t v, const int32_t *star, size_t n, uint8_t *cur,
                   uint8_t *next);

/* Mark in cur the vertices of domain triangles with an angle outside [55, 65]
 * degrees (the others are left alone by the smart rule anyway). */
void cvm__sm_mark_imperfect(const cvm__tri2 *T, uint8_t *cur);

/* The first marks when only the vertices v >= first with only[v] may move:
 * cvm__sm_mark_imperfect (then cvm__sm_dilate when dilate is set) restricted to them,
 * from their stars instead of a scan of every triangle; tmp is scratch of
 * T->nv bytes. */
void cvm__sm_mark_only(const cvm__tri2 *T, size_t first, const uint8_t *only, int dilate,
                       uint8_t *cur, uint8_t *tmp);

/* Add to cur every vertex sharing a domain triangle with a marked one; tmp
 * is scratch of T->nv bytes. */
void cvm__sm_dilate(const cvm__tri2 *T, uint8_t *cur, uint8_t *tmp);

#endif
