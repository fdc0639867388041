/* expansion.c - sums, scalings and estimates of nonoverlapping expansions (Shewchuk 1997, sec. 2). */
#include <float.h>
#include <math.h>

#include "geom/expansion.h"

/* Shewchuk's Grow-Expansion with zero elimination: add one double. */
int cvm__grow_expansion_zeroelim(int elen, const double *e, double b, double *h)
{
    double q = b, hh;
    int i, hn = 0;
    for (i = 0; i < elen; i++) {
        cvm__two_sum(q, e[i], &q, &hh);
        if (hh != 0.0)
            h[hn++] = hh;
    }
    if (q != 0.0 || hn == 0)
        h[hn++] = q;
    return hn;
}

/* Nonzero when e's head should be merged before f's: the smaller magnitude goes first. */
static int expansion_take_e(double enow, double fnow)
{
    return (fnow > enow) == (fnow > -enow);
}

/* Shewchuk's Fast-Expansion-Sum with zero elimination: merge e and f by
 * magnitude, then carry a running sum q through Two-Sum. Never reads past the
 * end of e or f. */
int cvm__fast_expansion_sum_zeroelim(int elen, const double *e, int flen, const double *f,
                                     double *h)
{
    double q, hh;
    int ei = 0, fi = 0, hn = 0;

    if (expansion_take_e(e[0], f[0]))
        q = e[ei++];
    else
        q = f[fi++];
    if (ei < elen && fi < flen) {
        /* The second component is at least as large as q: Fast-Two-Sum is exact. */
        if (expansion_take_e(e[ei], f[fi]))
            cvm__fast_two_sum(e[ei++], q, &q, &hh);
        else
            cvm__fast_two_sum(f[fi++], q, &q, &hh);
        if (hh != 0.0)
            h[hn++] = hh;
        while (ei < elen && fi < flen) {
            if (expansion_take_e(e[ei], f[fi]))
                cvm__two_sum(q, e[ei++], &q, &hh);
            else
                cvm__two_sum(q, f[fi++], &q, &hh);
            if (hh != 0.0)
                h[hn++] = hh;
        }
    }
    while (ei < elen) {
        cvm__two_sum(q, e[ei++], &q, &hh);
        if (hh != 0.0)
            h[hn++] = hh;
    }
    while (fi < flen) {
        cvm__two_sum(q, f[fi++], &q, &hh);
        if (hh != 0.0)
            h[hn++] = hh;
    }
    if (q != 0.0 || hn == 0)
        h[hn++] = q;
    return hn;
}

/* Shewchuk's Scale-Expansion with zero elimination: each component times b
 * by Two-Product, the partial products carried upwards by Two-Sum and
 * Fast-Two-Sum. b is split once. */
int cvm__scale_expansion_zeroelim(int elen, const double *e, double b, double *h)
{
    double bhi = 0.0, blo = 0.0, q, hh, p1, p0, sum;
    int i, hn = 0;

#if !defined(FP_FAST_FMA)
    cvm__split(b, &bhi, &blo);
#endif
    q = e[0] * b;
    hh = cvm__two_product_tail(e[0], b, bhi, blo, q);
    if (hh != 0.0)
        h[hn++] = hh;
    for (i = 1; i < elen; i++) {
        p1 = e[i] * b;
        p0 = cvm__two_product_tail(e[i], b, bhi, blo, p1);
        cvm__two_sum(q, p0, &sum, &hh);
        if (hh != 0.0)
            h[hn++] = hh;
        cvm__fast_two_sum(p1, sum, &q, &hh);
        if (hh != 0.0)
            h[hn++] = hh;
    }
    if (q != 0.0 || hn == 0)
        h[hn++] = q;
    return hn;
}

double cvm__estimate(int elen, const double *e)
{
    double q = e[0];
    int i;
    for (i = 1; i < elen; i++)
        q += e[i];
    return q;
}

int cvm__rescale_exponent(double m)
{
    int ex;
    if (m == 0.0 || (m >= 0x1p-60 && m <= 0x1p60))
        return 0;
    (void)frexp(m, &ex); /* m = f * 2^ex, f in [1/2, 1) */
    return 1 - ex;
}

double cvm__unscale(double det, int degree, int k)
{
    double r;
    if (det == 0.0 || k == 0)
        return det;
    r = ldexp(det, -degree * k);
    if (r == 0.0)
        return det > 0.0 ? 0x1p-1074 : -0x1p-1074;
    if (r > DBL_MAX)
        return DBL_MAX;
    if (r < -DBL_MAX)
        return -DBL_MAX;
    return r;
}
