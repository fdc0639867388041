/*
 * dual_internal.h - the power (weighted Voronoi) dual of a 2D triangulation:
 * the power vertex of a triangle (construction, inexact) and the exact test
 * that decides on which side of a triangle's edge that vertex lies.
 *
 * Convention: the power distance of x to the weighted point (p, w) is
 * |x - p|^2 - w (w in squared length units). The power vertex (orthocentre)
 * of a triangle has equal power distance to its three weighted corners; with
 * all weights 0 it is the circumcentre.
 */
#ifndef CVM_DUAL_INTERNAL_H
#define CVM_DUAL_INTERNAL_H

#include <stdint.h>

/* Power vertex of the non-degenerate triangle a, b, c with weights wa, wb, wc
 * into out[2]: plain doubles, possibly inexact (a construction). */
void cvm__power_vertex2d(const double *a, const double *b, const double *c, double wa, double wb,
                         double wc, double *out);

/* Exact side of the power vertex V of triangle a, b, c (counter-clockwise,
 * non-degenerate) relative to its edge a-b: +1 when V lies strictly on c's side
 * of the line ab, 0 on it, -1 beyond it. It is the sign of
 *   |B|^2 (|C|^2 + wa - wc) - (B.C) (|B|^2 + wa - wb),   B = b - a, C = c - a,
 * which is 2 D (B x V) with D = B x C > 0 (derivation in power_side.c),
 * so its sign is that of orient2d(a, b, V); with zero weights it is the sign of (a - c).(b - c), i.e. +1
 * iff the angle at c is acute. A floating-point filter, then exact expansion
 * arithmetic; exact over the range of the predicates in geom_internal.h
 * (treat sqrt|w| as a coordinate). Pure. */
int cvm__power_side2d(const double *a, const double *b, const double *c, double wa, double wb,
                      double wc);

/* Power-bisector foot of edge a-b: the point of line ab with equal power
 * distance to (a, wa) and (b, wb), into out[2] (inexact; a != b). */
void cvm__power_foot2d(const double *a, const double *b, double wa, double wb, double *out);

#endif
