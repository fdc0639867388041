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

/* out = (px^2 + py^2) * m exactly, m a minor of mn <= 4 components; returns
 * the length (<= 32). The lift is formed first (at most 4 components, usually
 * 1 for integer-like input), then each of its components scales m. */
static int incircle_lift_minor(int mn, const double *m, double px, double py, double *out)
{
    double x1, x0, y1, y0, lift[4], t[8], acc[2][32];
    int i, ln = 0, tn, n, cur = 0;
    cvm__two_product(px, px, &x1, &x0);
    cvm__two_product(py, py, &y1, &y0);
    if (x0 == 0.0 && y0 == 0.0) { /* exact squares */
        cvm__two_sum(x1, y1, &lift[1], &lift[0]);
        ln = 2;
        if (lift[0] == 0.0)
            lift[0] = lift[1], ln = 1;
    } else {
        double e[2], f[2];
        e[0] = x0, e[1] = x1, f[0] = y0, f[1] = y1;
        ln = cvm__fast_expansion_sum_zeroelim(2, e, 2, f, lift);
    }
    n = cvm__scale_expansion_zeroelim(mn, m, lift[0], acc[0]);
    for (i = 1; i < ln; i++) {
        tn = cvm__scale_expansion_zeroelim(mn, m, lift[i], t);
        n = cvm__fast_expansion_sum_zeroelim(n, acc[cur], tn, t, acc[1 - cur]);
        cur = 1 - cur;
    }
    for (i = 0; i < n; i++)
        out[i] = acc[cur][i];
    return n;
}

/* Stages B, C, then the exact expansion, on inputs already in the safe range. */
/*
 * Exactness certificate for lattice-like input, the usual source of exact
 * cocircular ties: when the six differences were computed exactly and are,
 * after one common power-of-two scaling, integers of magnitude at most 2^12,
 * every lift and minor is below 2^25, each lift times minor below 2^50, and
 * every product in the plain formula is exact in double, so that formula is
 * the exact determinant. Returns 1 and *det_out, or 0 when not certified.
 */
static int incircle_small_integer(const double *a, const double *b, const double *c,
                                  const double *d, const double *dd, double *det_out)
{
    double m = 0.0, sc;
    int i, ex;
    const double *p[3];
    p[0] = a, p[1] = b, p[2] = c;
    for (i = 0; i < 3; i++) {
        if (cvm__two_diff_tail(p[i][0], d[0], dd[2 * i]) != 0.0 ||
            cvm__two_diff_tail(p[i][1], d[1], dd[2 * i + 1]) != 0.0)
            return 0;
    }
    for (i = 0; i < 6; i++)
        m = fabs(dd[i]) > m ? fabs(dd[i]) : m;
    if (m == 0.0) {
        *det_out = 0.0;
        return 1;
    }
    (void)frexp(m, &ex);
    sc = ldexp(1.0, 12 - ex); /* m * sc in [2^11, 2^12) */
    for (i = 0; i < 6; i++) {
        double t = dd[i] * sc;
        if (t != (double)(int32_t)t)
            return 0;
    }
    {
        double adx = dd[0], ady = dd[1], bdx = dd[2], bdy = dd[3], cdx = dd[4], cdy = dd[5];
        *det_out = (adx * adx + ady * ady) * (bdx * cdy - cdx * bdy)
                   + (bdx * bdx + bdy * bdy) * (cdx * ady - adx * cdy)
                   + (cdx * cdx + cdy * cdy) * (adx * bdy - bdx * ady);
    }
    return 1;
}

static double incircle_stages(const double *a, const double *b, const double *c, const double *d)
{
    double adx = a[0] - d[0], bdx = b[0] - d[0], cdx = c[0] - d[0];
    double ady = a[1] - d[1], bdy = b[1] - d[1], cdy = c[1] - d[1];
    double adxt, bdxt, cdxt, adyt, bdyt, cdyt;
    double bc[4], ca[4], ab[4], adet[32], bdet[32], cdet[32], abdet[64], fin[96];
    double permanent, det, errbound;
    int an, bn, cn, abn, fn;
    {
        double dd[6];
        dd[0] = adx, dd[1] = ady, dd[2] = bdx, dd[3] = bdy, dd[4] = cdx, dd[5] = cdy;
        if (incircle_small_integer(a, b, c, d, dd, &det))
            return det;
    }

    /* B: the exact determinant of the rounded differences. */
    an = cvm__cross_zeroelim(bdx, cdy, cdx, bdy, bc);
    bn = cvm__cross_zeroelim(cdx, ady, adx, cdy, ca);
    cn = cvm__cross_zeroelim(adx, bdy, bdx, ady, ab);
    an = incircle_lift_minor(an, bc, adx, ady, adet);
    bn = incircle_lift_minor(bn, ca, bdx, bdy, bdet);
    cn = incircle_lift_minor(cn, ab, cdx, cdy, cdet);
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
        m = cvm__maxabs(cvm__maxabs(m, p[i][0]), p[i][1]);
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
