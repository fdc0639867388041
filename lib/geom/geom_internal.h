/*
 * geom_internal.h - exact geometric predicates and inexact constructions.
 *
 * Predicates (Shewchuk, "Adaptive Precision Floating-Point Arithmetic and Fast
 * Robust Geometric Predicates", 1997): a floating-point filter with a proven
 * error bound, then adaptive expansion arithmetic; the returned sign is always
 * the sign of the exact determinant of the double inputs. Error bounds are
 * compile-time constants (no exactinit(), no global state).
 *
 * The *_sos variants add Simulation of Simplicity by point index so that they
 * never return 0 where the caller needs a decision.
 *
 * Requires IEEE 754 double arithmetic with round-to-nearest and no extended
 * precision (x87): build with -msse2 -mfpmath=sse on 32-bit x86, and never
 * with -ffast-math. Thread-safety: all functions are pure.
 */
#ifndef CVM_GEOM_INTERNAL_H
#define CVM_GEOM_INTERNAL_H

#include <stdint.h>

/* Sign convention: > 0 when a, b, c are counter-clockwise, < 0 clockwise,
 * 0 exactly collinear. The magnitude approximates twice the signed area. */
double cvm__orient2d(const double *a, const double *b, const double *c);

/* > 0 when d lies strictly inside the circle through a, b, c, provided a, b, c
 * are counter-clockwise (the sign flips when they are clockwise); 0 when
 * cocircular. */
double cvm__incircle(const double *a, const double *b, const double *c, const double *d);

/* incircle with symbolic perturbation: each point i is lifted by eps^(f(i)),
 * where a larger index is lifted more (so the point of largest index among
 * exactly cocircular ones counts as outside). Precondition: a, b, c strictly
 * counter-clockwise, and the four points pairwise distinct. Returns +1 (d
 * inside) or -1 (outside), never 0. ia..id are the points' indices, distinct. */
int cvm__incircle_sos(const double *a, const double *b, const double *c, const double *d,
                      int64_t ia, int64_t ib, int64_t ic, int64_t id);

/* Power (weighted in-circle) test, weights in squared length units, power
 * distance |x - p|^2 - w. > 0 when the weighted point (d, wd) is in conflict
 * with the orthocircle of (a,wa), (b,wb), (c,wc) (a, b, c counter-clockwise),
 * i.e. the lifted point d' = (d, |d|^2 - wd) lies below the plane through the
 * lifted a', b', c'. With all weights 0 it equals incircle's sign. */
double cvm__power2d(const double *a, const double *b, const double *c, const double *d,
                    double wa, double wb, double wc, double wd);

/* power2d with the same symbolic perturbation as incircle_sos. */
int cvm__power2d_sos(const double *a, const double *b, const double *c, const double *d,
                     double wa, double wb, double wc, double wd,
                     int64_t ia, int64_t ib, int64_t ic, int64_t id);

/* > 0 when d lies below the plane through a, b, c, where a, b, c appear
 * counter-clockwise seen from above (Shewchuk's convention: positive when d
 * sees a, b, c clockwise... i.e. the sign of det[a-d; b-d; c-d]). */
double cvm__orient3d(const double *a, const double *b, const double *c, const double *d);

/* > 0 when e lies inside the sphere through a, b, c, d, provided
 * orient3d(a, b, c, d) > 0; 0 when cospherical. */
double cvm__insphere(const double *a, const double *b, const double *c, const double *d,
                     const double *e);

/* Constructions: plain doubles, possibly inexact; every later decision about
 * their result is taken by the exact predicates above. */

/* Circumcentre of triangle a, b, c (non-degenerate) into out[2]. */
void cvm__circumcenter2d(const double *a, const double *b, const double *c, double *out);

/* Intersection point of lines ab and cd (which properly cross) into out[2];
 * the result is clamped to lie within the bounding boxes of both segments. */
void cvm__segment_intersection2d(const double *a, const double *b, const double *c,
                                 const double *d, double *out);

#endif
