/* construct.c - inexact 2D constructions: circumcentre and segment crossing point. */
#include <math.h>

#include "geom/geom_internal.h"

/* Relative to a: with b' = b - a, c' = c - a and D = 2 (b' x c'), the centre is
 * a + (cy'|b'|^2 - by'|c'|^2, bx'|c'|^2 - cx'|b'|^2) / D. D comes from the exact
 * orient2d, so its sign is right even for thin triangles. */
void cvm__circumcenter2d(const double *a, const double *b, const double *c, double *out)
{
    double bx = b[0] - a[0], by = b[1] - a[1];
    double cx = c[0] - a[0], cy = c[1] - a[1];
    double b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
    double denom = 2.0 * cvm__orient2d(a, b, c);
    out[0] = a[0] + (cy * b2 - by * c2) / denom;
    out[1] = a[1] + (bx * c2 - cx * b2) / denom;
}

static double construct_clamp(double v, double lo, double hi)
{
    return v < lo ? lo : (v > hi ? hi : v);
}

/* a + t (b - a) with t = o(c,d,a) / (o(c,d,a) - o(c,d,b)); the two exact
 * orientations have opposite signs for a proper crossing, so the denominator
 * does not cancel and t lies in [0, 1]. */
void cvm__segment_intersection2d(const double *a, const double *b, const double *c,
                                 const double *d, double *out)
{
    double oa = cvm__orient2d(c, d, a), ob = cvm__orient2d(c, d, b);
    double t = oa / (oa - ob);
    double lo, hi;
    int i;
    if (!(t >= 0.0))
        t = 0.0; /* also catches NaN from a degenerate call */
    if (t > 1.0)
        t = 1.0;
    for (i = 0; i < 2; i++) {
        lo = fmax(fmin(a[i], b[i]), fmin(c[i], d[i]));
        hi = fmin(fmax(a[i], b[i]), fmax(c[i], d[i]));
        out[i] = construct_clamp(a[i] + t * (b[i] - a[i]), lo, hi);
    }
}
