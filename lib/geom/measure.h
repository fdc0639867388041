/*
 * measure.h - the one home of the plain-double measures of 2D triangles:
 * angles, sin^2 of the smallest angle, areas, circumradii, and pi.
 *
 * These are measures, not decisions: they round, and no topological choice
 * may rest on their sign (the exact predicates in geom_internal.h take those).
 * Where two functions below compute the same quantity they round differently,
 * and each caller keeps the rounding it was tuned with, so that no mesh
 * changes; each such pair says where it differs.
 *
 * Points are 2 doubles (x, y). Angles are radians unless the name says deg.
 * Thread-safety: all functions are pure.
 */
#ifndef CVM_GEOM_MEASURE_H
#define CVM_GEOM_MEASURE_H

/* pi to the precision of a double (the literal rounds to the nearest double). */
#define CVM__PI 3.14159265358979323846

/* |a - b|^2. Inline: the optimiser's objective calls it in its inner loop. */
static inline double cvm__dist2(const double *a, const double *b)
{
    return (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]);
}

/* (b - a) x (c - a): twice the signed area of a, b, c, positive when they are
 * counter-clockwise. Rounded; use cvm__orient2d for a sign that decides. Inline
 * like cvm__dist2. */
static inline double cvm__cross2(const double *a, const double *b, const double *c)
{
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

/* Signed area of triangle a, b, c (positive counter-clockwise), and its
 * absolute value. */
double cvm__tri_area(const double *a, const double *b, const double *c);
double cvm__tri_area_abs(const double *a, const double *b, const double *c);

/* Squared circumradius of a, b, c: |bc|^2 |ca|^2 |ab|^2 / (4 cross^2);
 * +inf or NaN for a degenerate triangle. (The circumcentre is the
 * construction cvm__circumcenter2d in geom_internal.h.) */
double cvm__circumradius2(const double *a, const double *b, const double *c);

/* The same from the squared sides l0 = |bc|^2, l1 = |ca|^2, l2 = |ab|^2 and
 * cross = (b - a) x (c - a): ((l0 l1) l2) / ((4 cross) cross). */
double cvm__circumradius2_sides(double l0, double l1, double l2, double cross);

/* Angle between the vectors u and w, in [0, pi]: atan2(|u x w|, u . w). */
double cvm__vec_angle(double ux, double uy, double wx, double wy);

/* Interior angle at o of the triangle o, a, b (in [0, pi]). */
double cvm__corner_angle(const double *o, const double *a, const double *b);

/* The angle at o between o->a and o->b measured in the metric g = (g11, g12,
 * g22) (the inner product u^T g v), degrees, in [0, 180]. */
double cvm__metric_angle_deg(const double g[3], const double *o, const double *a,
                             const double *b);

/* Turning angle at b of the path a -> b -> c (0 straight on, pi straight back). */
double cvm__turn_angle(const double *a, const double *b, const double *c);

/* Smallest interior angle of triangle a, b, c in degrees: the smallest of the
 * three corner angles, each times (180 / pi), and never above 180. */
double cvm__tri_min_angle_deg(const double *a, const double *b, const double *c);

/*
 * Range-safe variants, for measures reported on any finite input: near the
 * limits of the double range (an edge vector beyond 2^500 or below 2^-500, or
 * a difference that overflows) each edge vector is scaled by a power of two
 * before the products, so angles stay right where plain products would give
 * inf - inf, and areas are scaled back (inf only when the true area exceeds
 * the largest double). Inside that range they round as the plain functions
 * (cvm__corner_angle(a, b, c) * (180.0 / CVM__PI), cvm__cross2 / 2).
 */
/* Angle at a of triangle a, b, c in degrees; *dot receives the dot product of
 * the two edge vectors (times a positive factor outside the safe range). */
double cvm__corner_angle_deg_safe(const double *a, const double *b, const double *c, double *dot);
/* Signed area of triangle a, b, c (positive counter-clockwise). */
double cvm__tri_area_safe(const double *a, const double *b, const double *c);
/* Smallest angle of triangle a, b, c in degrees: the smallest of the three
 * cvm__corner_angle_deg_safe (no cap at 180, unlike cvm__tri_min_angle_deg). */
double cvm__min_angle_deg(const double *a, const double *b, const double *c);

/*
 * sin^2 of the smallest angle. By the law of sines the smallest angle faces
 * the shortest side, so sin^2 = cross^2 |shortest|^2 / (|bc|^2 |ca|^2 |ab|^2)
 * (cross = twice the signed area). Three roundings of it are in use:
 *
 * cvm__min_sin2: sides ab, bc, ca, computed as (cross^2 |shortest|^2) / ((ab bc) ca);
 *   0 when a side is 0; either orientation gives the same value.
 * cvm__min_sin2_ccw: sides l0 = |bc|^2, l1 = |ca|^2, l2 = |ab|^2, computed as
 *   ((|shortest|^2 cross) cross) / ((l0 l1) l2) (cvm__min_sin2_sides); 0 unless
 *   a, b, c are counter-clockwise (cross > 0). The refiners' measure.
 * cvm__min_sin2_corners: the smallest over the corners of cross^2 / (product of
 *   the two sides at the corner), HUGE_VAL when every corner gives NaN (all
 *   three points equal); either orientation gives the same value. The dual
 *   optimiser's measure.
 */
double cvm__min_sin2(const double *a, const double *b, const double *c);
double cvm__min_sin2_ccw(const double *a, const double *b, const double *c);
double cvm__min_sin2_corners(const double *a, const double *b, const double *c);

/* The formula of cvm__min_sin2_ccw from the squared sides l0 (opposite the
 * first corner), l1, l2 and cross, for callers that have them already. No
 * orientation test. */
double cvm__min_sin2_sides(double l0, double l1, double l2, double cross);

#endif
