/* power2d.c - exact 2D power (weighted in-circle) test: filter, exact stage B, then an exact expansion. */
#include <math.h>

#include "geom/exact_det.h"
#include "geom/expansion.h"
#include "geom/geom_internal.h"

/*
 * det [adx ady alift; bdx bdy blift; cdx cdy clift] with p.d = p - d and
 * plift = |p - d|^2 - (wp - wd): the 4x4 determinant [x y |x|^2-w 1] after
 * subtracting row d and the multiple 2 d.(p - d) of the first two columns.
 *
 * Filter bound (our derivation, in the style of Shewchuk's): expand det into
 * monomials of the exact differences. Each monomial picks up at most 12
 * rounding factors (1 + delta), |delta| <= eps: 2 for the squared difference,
 * 1 square, 1 sum of squares, 1 weight subtraction, 2 for the differences in the
 * minor, 1 product, 1 minor subtraction, 1 lift * minor, 2 for the final sum. So
 * |error| <= gamma_12 * P, P the sum of |monomials|, and P is at most
 * (1 + 11 eps + O(eps^2)) times the permanent below computed in floating point
 * (4 differences, 7 roundings, all terms nonnegative). 12 + 512 eps covers
 * the eps^2 terms and the rounding of the bound itself. Stage B computes the
 * exact determinant of the rounded differences (4 of them per monomial at most):
 * (4 + 50 eps) eps, rounded up to 5 + 96 eps to absorb the estimate's error.
 */
static const double pow_errbound_a = (12.0 + 512.0 * CVM__EPS) * CVM__EPS;
static const double pow_errbound_b = (5.0 + 96.0 * CVM__EPS) * CVM__EPS;

/* out = ((px^2 + py^2) - w) * m exactly, m a minor of mn <= 4 components; length <= 40. */
static int power_lift_minor(int mn, const double *m, double px, double py, double w, double *out)
{
    double t8[8], xx[16], yy[16], sq[32];
    int n8, nx, ny, nsq;
    n8 = cvm__scale_expansion_zeroelim(mn, m, px, t8);
    nx = cvm__scale_expansion_zeroelim(n8, t8, px, xx);
    n8 = cvm__scale_expansion_zeroelim(mn, m, py, t8);
    ny = cvm__scale_expansion_zeroelim(n8, t8, py, yy);
    nsq = cvm__fast_expansion_sum_zeroelim(nx, xx, ny, yy, sq);
    if (w == 0.0)
        return cvm__fast_expansion_sum_zeroelim(nsq, sq, 1, &w, out);
    n8 = cvm__scale_expansion_zeroelim(mn, m, -w, t8);
    return cvm__fast_expansion_sum_zeroelim(nsq, sq, n8, t8, out);
}

/* Stage B, then the exact expansion, on inputs already in the safe range. */
static double power2d_stages(const double *a, const double *b, const double *c, const double *d,
                             double wa, double wb, double wc, double wd)
{
    double adx = a[0] - d[0], bdx = b[0] - d[0], cdx = c[0] - d[0];
    double ady = a[1] - d[1], bdy = b[1] - d[1], cdy = c[1] - d[1];
    double wad = wa - wd, wbd = wb - wd, wcd = wc - wd;
    double bc[4], ca[4], ab[4], adet[40], bdet[40], cdet[40], abdet[80], fin[120];
    double permanent, det, errbound;
    int an, bn, cn, abn, fn;

    an = cvm__cross_zeroelim(bdx, cdy, cdx, bdy, bc);
    bn = cvm__cross_zeroelim(cdx, ady, adx, cdy, ca);
    cn = cvm__cross_zeroelim(adx, bdy, bdx, ady, ab);
    an = power_lift_minor(an, bc, adx, ady, wad, adet);
    bn = power_lift_minor(bn, ca, bdx, bdy, wbd, bdet);
    cn = power_lift_minor(cn, ab, cdx, cdy, wcd, cdet);
    abn = cvm__fast_expansion_sum_zeroelim(an, adet, bn, bdet, abdet);
    fn = cvm__fast_expansion_sum_zeroelim(abn, abdet, cn, cdet, fin);
    det = cvm__estimate(fn, fin);
    permanent = (fabs(bdx * cdy) + fabs(cdx * bdy)) * ((adx * adx + ady * ady) + fabs(wad))
                + (fabs(cdx * ady) + fabs(adx * cdy)) * ((bdx * bdx + bdy * bdy) + fabs(wbd))
                + (fabs(adx * bdy) + fabs(bdx * ady)) * ((cdx * cdx + cdy * cdy) + fabs(wcd));
    errbound = pow_errbound_b * permanent;
    if (det >= errbound || -det >= errbound)
        return det;
    if (cvm__two_diff_tail(a[0], d[0], adx) == 0.0 && cvm__two_diff_tail(a[1], d[1], ady) == 0.0
        && cvm__two_diff_tail(b[0], d[0], bdx) == 0.0
        && cvm__two_diff_tail(b[1], d[1], bdy) == 0.0
        && cvm__two_diff_tail(c[0], d[0], cdx) == 0.0
        && cvm__two_diff_tail(c[1], d[1], cdy) == 0.0 && cvm__two_diff_tail(wa, wd, wad) == 0.0
        && cvm__two_diff_tail(wb, wd, wbd) == 0.0 && cvm__two_diff_tail(wc, wd, wcd) == 0.0)
        return det; /* every difference was exact, so B was the exact value */
    return cvm__power2d_exact(a, b, c, d, wa, wb, wc, wd);
}

static CVM__NOINLINE double power2d_adapt(const double *a, const double *b, const double *c,
                                          const double *d, double wa, double wb, double wc,
                                          double wd)
{
    const double *p[4];
    double s[4][2], w[4], m = 0.0, mw;
    int i, k;
    p[0] = a, p[1] = b, p[2] = c, p[3] = d;
    w[0] = wa, w[1] = wb, w[2] = wc, w[3] = wd;
    mw = cvm__maxabs(cvm__maxabs(cvm__maxabs(fabs(wa), wb), wc), wd);
    for (i = 0; i < 4; i++)
        m = cvm__maxabs(cvm__maxabs(m, p[i][0]), p[i][1]);
    k = cvm__rescale_exponent(cvm__maxabs(m, sqrt(mw)));
    if (k == 0)
        return power2d_stages(a, b, c, d, wa, wb, wc, wd);
    for (i = 0; i < 4; i++) {
        s[i][0] = ldexp(p[i][0], k), s[i][1] = ldexp(p[i][1], k);
        w[i] = ldexp(w[i], 2 * k);
    }
    return cvm__unscale(power2d_stages(s[0], s[1], s[2], s[3], w[0], w[1], w[2], w[3]), 4, k);
}

double cvm__power2d(const double *a, const double *b, const double *c, const double *d,
                    double wa, double wb, double wc, double wd)
{
    double adx = a[0] - d[0], bdx = b[0] - d[0], cdx = c[0] - d[0];
    double ady = a[1] - d[1], bdy = b[1] - d[1], cdy = c[1] - d[1];
    double wad = wa - wd, wbd = wb - wd, wcd = wc - wd;
    double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy;
    double cdxady = cdx * ady, adxcdy = adx * cdy;
    double adxbdy = adx * bdy, bdxady = bdx * ady;
    double asq = adx * adx + ady * ady, bsq = bdx * bdx + bdy * bdy, csq = cdx * cdx + cdy * cdy;
    double det = (asq - wad) * (bdxcdy - cdxbdy) + (bsq - wbd) * (cdxady - adxcdy)
                 + (csq - wcd) * (adxbdy - bdxady);
    double permanent = (fabs(bdxcdy) + fabs(cdxbdy)) * (asq + fabs(wad))
                       + (fabs(cdxady) + fabs(adxcdy)) * (bsq + fabs(wbd))
                       + (fabs(adxbdy) + fabs(bdxady)) * (csq + fabs(wcd));
    double errbound = pow_errbound_a * permanent + cvm__filter_floor;
    if (fabs(det) > errbound)
        return det;
    return power2d_adapt(a, b, c, d, wa, wb, wc, wd);
}

/* The 4x4 determinant [x y x^2+y^2-w 1] expanded along the lifted column. */
CVM__NOINLINE double cvm__power2d_exact(const double *a, const double *b, const double *c,
                                        const double *d, double wa, double wb, double wc,
                                        double wd)
{
    double t[12], u[4][120], v[2][240], fin[480];
    int tn, n[4], m0, m1, fn;
    tn = cvm__orient2d_raw(b, c, d, t);
    n[0] = cvm__lift_scale(tn, t, a, 2, wa, 1.0, u[0]);
    tn = cvm__orient2d_raw(a, c, d, t);
    n[1] = cvm__lift_scale(tn, t, b, 2, wb, -1.0, u[1]);
    tn = cvm__orient2d_raw(a, b, d, t);
    n[2] = cvm__lift_scale(tn, t, c, 2, wc, 1.0, u[2]);
    tn = cvm__orient2d_raw(a, b, c, t);
    n[3] = cvm__lift_scale(tn, t, d, 2, wd, -1.0, u[3]);
    m0 = cvm__fast_expansion_sum_zeroelim(n[0], u[0], n[1], u[1], v[0]);
    m1 = cvm__fast_expansion_sum_zeroelim(n[2], u[2], n[3], u[3], v[1]);
    fn = cvm__fast_expansion_sum_zeroelim(m0, v[0], m1, v[1], fin);
    return fin[fn - 1];
}
