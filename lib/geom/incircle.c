/* incircle.c - exact 2D in-circle test: filter, adaptive stages B and C, then an exact expansion. */
#include <math.h>

#include "geom/exact_det.h"
#include "geom/expansion.h"
#include "geom/geom_internal.h"

/* Shewchuk's iccerrboundB and iccerrboundC (stage A's bound is in geom_internal.h). */
static const double icc_errbound_b = (4.0 + 48.0 * CVM__EPS) * CVM__EPS;
static const double icc_errbound_c = (44.0 + 576.0 * CVM__EPS) * CVM__EPS * CVM__EPS;

double cvm__incircle(const double *a, const double *b, const double *c, const double *d)
{
    return cvm__incircle_inline(a, b, c, d);
}

/* out = (px^2 + py^2) * m exactly, m a 4-component minor; returns the length (<= 32). */
static int incircle_lift_minor(const double *m, double px, double py, double *out)
{
    double t8[8], xx[16], yy[16];
    int n8, nx, ny;
    n8 = cvm__scale_expansion_zeroelim(4, m, px, t8);
    nx = cvm__scale_expansion_zeroelim(n8, t8, px, xx);
    n8 = cvm__scale_expansion_zeroelim(4, m, py, t8);
    ny = cvm__scale_expansion_zeroelim(n8, t8, py, yy);
    return cvm__fast_expansion_sum_zeroelim(nx, xx, ny, yy, out);
}

/* out[0..3] = px*qy - qx*py exactly. */
static void incircle_minor(double px, double py, double qx, double qy, double *out)
{
    double l1, l0, r1, r0;
    cvm__two_product(px, qy, &l1, &l0);
    cvm__two_product(qx, py, &r1, &r0);
    cvm__two_two_diff(l1, l0, r1, r0, out);
}

/* Stages B, C, then the exact expansion, on inputs already in the safe range. */
static double incircle_stages(const double *a, const double *b, const double *c, const double *d)
{
    double adx = a[0] - d[0], bdx = b[0] - d[0], cdx = c[0] - d[0];
    double ady = a[1] - d[1], bdy = b[1] - d[1], cdy = c[1] - d[1];
    double adxt, bdxt, cdxt, adyt, bdyt, cdyt;
    double bc[4], ca[4], ab[4], adet[32], bdet[32], cdet[32], abdet[64], fin[96];
    double permanent, det, errbound;
    int an, bn, cn, abn, fn;

    /* B: the exact determinant of the rounded differences. */
    incircle_minor(bdx, bdy, cdx, cdy, bc);
    incircle_minor(cdx, cdy, adx, ady, ca);
    incircle_minor(adx, ady, bdx, bdy, ab);
    an = incircle_lift_minor(bc, adx, ady, adet);
    bn = incircle_lift_minor(ca, bdx, bdy, bdet);
    cn = incircle_lift_minor(ab, cdx, cdy, cdet);
    abn = cvm__fast_expansion_sum_zeroelim(an, adet, bn, bdet, abdet);
    fn = cvm__fast_expansion_sum_zeroelim(abn, abdet, cn, cdet, fin);
    det = cvm__estimate(fn, fin);
    permanent = (fabs(bdx * cdy) + fabs(cdx * bdy)) * (adx * adx + ady * ady)
                + (fabs(cdx * ady) + fabs(adx * cdy)) * (bdx * bdx + bdy * bdy)
                + (fabs(adx * bdy) + fabs(bdx * ady)) * (cdx * cdx + cdy * cdy);
    errbound = icc_errbound_b * permanent;
    if (det >= errbound || -det >= errbound)
        return det;

    adxt = cvm__two_diff_tail(a[0], d[0], adx);
    bdxt = cvm__two_diff_tail(b[0], d[0], bdx);
    cdxt = cvm__two_diff_tail(c[0], d[0], cdx);
    adyt = cvm__two_diff_tail(a[1], d[1], ady);
    bdyt = cvm__two_diff_tail(b[1], d[1], bdy);
    cdyt = cvm__two_diff_tail(c[1], d[1], cdy);
    if (adxt == 0.0 && bdxt == 0.0 && cdxt == 0.0 && adyt == 0.0 && bdyt == 0.0 && cdyt == 0.0)
        return det; /* the differences were exact, so B was the exact value */

    /* C: first-order tail terms, lift * d(minor) + d(lift) * minor, per row. */
    errbound = icc_errbound_c * permanent + CVM__RESULTERRBOUND * fabs(det);
    det += ((adx * adx + ady * ady) * ((bdx * cdyt + cdy * bdxt) - (bdy * cdxt + cdx * bdyt))
            + 2.0 * (adx * adxt + ady * adyt) * (bdx * cdy - bdy * cdx))
           + ((bdx * bdx + bdy * bdy) * ((cdx * adyt + ady * cdxt) - (cdy * adxt + adx * cdyt))
              + 2.0 * (bdx * bdxt + bdy * bdyt) * (cdx * ady - cdy * adx))
           + ((cdx * cdx + cdy * cdy) * ((adx * bdyt + bdy * adxt) - (ady * bdxt + bdx * adyt))
              + 2.0 * (cdx * cdxt + cdy * cdyt) * (adx * bdy - ady * bdx));
    if (det >= errbound || -det >= errbound)
        return det;

    return cvm__incircle_exact(a, b, c, d);
}

CVM__NOINLINE double cvm__incircle_adapt(const double *a, const double *b, const double *c,
                                         const double *d)
{
    const double *p[4];
    double s[4][2], m = 0.0;
    int i, k;
    p[0] = a, p[1] = b, p[2] = c, p[3] = d;
    for (i = 0; i < 4; i++)
        m = fmax(m, fmax(fabs(p[i][0]), fabs(p[i][1])));
    k = cvm__rescale_exponent(m);
    if (k == 0)
        return incircle_stages(a, b, c, d);
    for (i = 0; i < 4; i++)
        s[i][0] = ldexp(p[i][0], k), s[i][1] = ldexp(p[i][1], k);
    return cvm__unscale(incircle_stages(s[0], s[1], s[2], s[3]), 4, k);
}

/* The 4x4 determinant [x y x^2+y^2 1] expanded along the lifted column:
 * lift(a) T(b,c,d) - lift(b) T(a,c,d) + lift(c) T(a,b,d) - lift(d) T(a,b,c). */
CVM__NOINLINE double cvm__incircle_exact(const double *a, const double *b, const double *c,
                                         const double *d)
{
    double t[12], u[4][96], v[2][192], fin[384];
    int tn, n[4], m0, m1, fn;
    tn = cvm__orient2d_raw(b, c, d, t);
    n[0] = cvm__lift_scale(tn, t, a, 2, 0.0, 1.0, u[0]);
    tn = cvm__orient2d_raw(a, c, d, t);
    n[1] = cvm__lift_scale(tn, t, b, 2, 0.0, -1.0, u[1]);
    tn = cvm__orient2d_raw(a, b, d, t);
    n[2] = cvm__lift_scale(tn, t, c, 2, 0.0, 1.0, u[2]);
    tn = cvm__orient2d_raw(a, b, c, t);
    n[3] = cvm__lift_scale(tn, t, d, 2, 0.0, -1.0, u[3]);
    m0 = cvm__fast_expansion_sum_zeroelim(n[0], u[0], n[1], u[1], v[0]);
    m1 = cvm__fast_expansion_sum_zeroelim(n[2], u[2], n[3], u[3], v[1]);
    fn = cvm__fast_expansion_sum_zeroelim(m0, v[0], m1, v[1], fin);
    return fin[fn - 1];
}
