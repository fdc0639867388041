/* orient2d.c - exact 2D orientation: filter, then Shewchuk's adaptive stages B, C and D. */
#include <math.h>

#include "geom/exact_det.h"
#include "geom/expansion.h"
#include "geom/geom_internal.h"

/* Shewchuk's ccwerrboundB and ccwerrboundC (stage A's bound is in geom_internal.h). */
static const double o2d_errbound_b = (2.0 + 12.0 * CVM__EPS) * CVM__EPS;
static const double o2d_errbound_c = (9.0 + 64.0 * CVM__EPS) * CVM__EPS * CVM__EPS;

double cvm__orient2d(const double *a, const double *b, const double *c)
{
    return cvm__orient2d_inline(a, b, c);
}

/* Stages B-D on inputs already in the safe range. */
static double orient2d_stages(const double *a, const double *b, const double *c)
{
    double acx = a[0] - c[0], bcx = b[0] - c[0];
    double acy = a[1] - c[1], bcy = b[1] - c[1];
    double acxtail, bcxtail, acytail, bcytail;
    double dl1, dl0, dr1, dr0, s1, s0, t1, t0, u[4], bb[4], c1[8], c2[12], dd[16];
    double detsum, det, errbound;
    int c1n, c2n, dn;

    /* B: the exact determinant of the rounded differences. */
    cvm__two_product(acx, bcy, &dl1, &dl0);
    cvm__two_product(acy, bcx, &dr1, &dr0);
    cvm__two_two_diff(dl1, dl0, dr1, dr0, bb);
    det = cvm__estimate(4, bb);
    detsum = fabs(dl1) + fabs(dr1);
    errbound = o2d_errbound_b * detsum;
    if (det >= errbound || -det >= errbound)
        return det;

    acxtail = cvm__two_diff_tail(a[0], c[0], acx);
    bcxtail = cvm__two_diff_tail(b[0], c[0], bcx);
    acytail = cvm__two_diff_tail(a[1], c[1], acy);
    bcytail = cvm__two_diff_tail(b[1], c[1], bcy);
    if (acxtail == 0.0 && acytail == 0.0 && bcxtail == 0.0 && bcytail == 0.0)
        return det; /* the differences were exact, so B was the exact value */

    /* C: add the first-order tail terms in floating point. */
    errbound = o2d_errbound_c * detsum + CVM__RESULTERRBOUND * fabs(det);
    det += (acx * bcytail + bcy * acxtail) - (acy * bcxtail + bcx * acytail);
    if (det >= errbound || -det >= errbound)
        return det;

    /* D: add every tail product exactly. */
    cvm__two_product(acxtail, bcy, &s1, &s0);
    cvm__two_product(acytail, bcx, &t1, &t0);
    cvm__two_two_diff(s1, s0, t1, t0, u);
    c1n = cvm__fast_expansion_sum_zeroelim(4, bb, 4, u, c1);
    cvm__two_product(acx, bcytail, &s1, &s0);
    cvm__two_product(acy, bcxtail, &t1, &t0);
    cvm__two_two_diff(s1, s0, t1, t0, u);
    c2n = cvm__fast_expansion_sum_zeroelim(c1n, c1, 4, u, c2);
    cvm__two_product(acxtail, bcytail, &s1, &s0);
    cvm__two_product(acytail, bcxtail, &t1, &t0);
    cvm__two_two_diff(s1, s0, t1, t0, u);
    dn = cvm__fast_expansion_sum_zeroelim(c2n, c2, 4, u, dd);
    return dd[dn - 1];
}

CVM__NOINLINE double cvm__orient2d_adapt(const double *a, const double *b, const double *c)
{
    double m = cvm__maxabs(cvm__maxabs(cvm__maxabs(fabs(a[0]), a[1]), b[0]), b[1]);
    m = cvm__maxabs(cvm__maxabs(m, c[0]), c[1]);
    int k = cvm__rescale_exponent(m);
    double sa[2], sb[2], sc[2];
    if (k == 0)
        return orient2d_stages(a, b, c);
    sa[0] = ldexp(a[0], k), sa[1] = ldexp(a[1], k);
    sb[0] = ldexp(b[0], k), sb[1] = ldexp(b[1], k);
    sc[0] = ldexp(c[0], k), sc[1] = ldexp(c[1], k);
    return cvm__unscale(orient2d_stages(sa, sb, sc), 2, k);
}

double cvm__orient2d_exact(const double *a, const double *b, const double *c)
{
    double h[12];
    int n = cvm__orient2d_raw(a, b, c, h);
    return h[n - 1];
}
