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

/* The crossing is interpolated along the shorter of the two segments, from
 * its end nearer to the crossing: p + t (q - p) with t = o(r,s,p) / (o(r,s,p)
 * - o(r,s,q)) in [0, 1/2]. The two exact orientations have opposite signs for
 * a proper crossing, so the denominator does not cancel, and the rounding
 * error is relative to the short segment, not to a far endpoint of the long
 * one (a segment reaching 1e24 crossed by unit segments once put the point a
 * billion units off). */
void cvm__segment_intersection2d(const double *a, const double *b, const double *c,
                                 const double *d, double *out)
{
    double lab = (b[0] - a[0]) * (b[0] - a[0]) + (b[1] - a[1]) * (b[1] - a[1]);
    double lcd = (d[0] - c[0]) * (d[0] - c[0]) + (d[1] - c[1]) * (d[1] - c[1]);
    const double *p = a, *q = b, *r = c, *s = d;
    double op, oq, t;
    double lo, hi;
    int i;
    if (lcd < lab) {
        p = c;
        q = d;
        r = a;
        s = b;
    }
    op = cvm__orient2d(r, s, p);
    oq = cvm__orient2d(r, s, q);
    t = op / (op - oq);
    if (!(t >= 0.0))
        t = 0.0; /* also catches NaN from a degenerate call */
    if (t > 1.0)
        t = 1.0;
    if (t > 0.5) {
        const double *x = p;
        p = q;
        q = x;
        t = 1.0 - t;
    }
    for (i = 0; i < 2; i++) {
        lo = fmax(fmin(a[i], b[i]), fmin(c[i], d[i]));
        hi = fmin(fmax(a[i], b[i]), fmax(c[i], d[i]));
        out[i] = construct_clamp(p[i] + t * (q[i] - p[i]), lo, hi);
    }
}
