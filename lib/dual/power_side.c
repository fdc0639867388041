/* power_side.c - the power vertex of a triangle and the exact side of it relative to an edge. */
#include <math.h>

#include "dual_internal.h"
#include "geom/expansion.h"

/*
 * Derivation. Put a at the origin: B = b - a, C = c - a, D = B x C > 0. The
 * power vertex V (relative to a) solves 2 B.V = beta_b, 2 C.V = beta_c with
 * beta_b = |B|^2 + wa - wb and beta_c = |C|^2 + wa - wc, so
 *   V = (C_y beta_b - B_y beta_c, B_x beta_c - C_x beta_b) / (2 D).
 * Its side of the line ab is the sign of B x V, and
 *   2 D (B x V) = B_x (B_x beta_c - C_x beta_b) - B_y (C_y beta_b - B_y beta_c)
 *               = |B|^2 beta_c - (B.C) beta_b.
 * With zero weights this is |B|^2 (|C|^2 - B.C) = |B|^2 (c - a).(c - b).
 */

void cvm__power_vertex2d(const double *a, const double *b, const double *c, double wa, double wb,
                         double wc, double *out)
{
    double bx = b[0] - a[0], by = b[1] - a[1], cx = c[0] - a[0], cy = c[1] - a[1];
    double d = 2.0 * (bx * cy - by * cx);
    double betab = bx * bx + by * by + (wa - wb), betac = cx * cx + cy * cy + (wa - wc);
    out[0] = a[0] + (cy * betab - by * betac) / d;
    out[1] = a[1] + (bx * betac - cx * betab) / d;
}

void cvm__power_foot2d(const double *a, const double *b, double wa, double wb, double *out)
{
    double bx = b[0] - a[0], by = b[1] - a[1], l2 = bx * bx + by * by;
    double s = 0.5 * (l2 + wa - wb) / l2;
    out[0] = a[0] + s * bx;
    out[1] = a[1] + s * by;
}

/* Sizes of the exact stage: a difference has 2 components, a product of an
 * m- and an n-component expansion at most 2mn. */
enum { E_SQ = 16, E_BETA = 18, E_TERM = 2 * E_SQ * E_BETA };

/* h = e * f (h distinct from both); returns the length of h. tmp needs 2*elen
 * and acc elen*flen*2 entries. */
static int mul(int elen, const double *e, int flen, const double *f, double *h, double *tmp,
               double *acc)
{
    int i, hlen = 1, n;
    h[0] = 0.0;
    for (i = 0; i < flen; i++) {
        n = cvm__scale_expansion_zeroelim(elen, e, f[i], tmp);
        hlen = cvm__fast_expansion_sum_zeroelim(hlen, h, n, tmp, acc);
        for (n = 0; n < hlen; n++)
            h[n] = acc[n];
    }
    return hlen;
}

/* x^2 + y^2 or x1*x2 + y1*y2 of 2-component expansions into h (<= 16). */
static int dot2(const double *x1, const double *y1, const double *x2, const double *y2, double *h)
{
    double p[8], q[8], tmp[4], acc[8];
    int np = mul(2, x1, 2, x2, p, tmp, acc);
    int nq = mul(2, y1, 2, y2, q, tmp, acc);
    return cvm__fast_expansion_sum_zeroelim(np, p, nq, q, h);
}

static int sign_of(int n, const double *e)
{
    double top = e[n - 1];
    return top > 0 ? 1 : top < 0 ? -1 : 0;
}

static CVM__NOINLINE int exact_side(const double *a, const double *b, const double *c, double wa,
                                    double wb, double wc)
{
    double bx[2], by[2], cx[2], cy[2], wab[2], wac[2];
    double bb[E_SQ], cc[E_SQ], bc[E_SQ], betab[E_BETA], betac[E_BETA];
    double t1[E_TERM], t2[E_TERM], det[2 * E_TERM], tmp[2 * E_SQ], acc[E_TERM];
    int nbb, ncc, nbc, nbeb, nbec, n1, n2, n, i;
    cvm__two_diff(b[0], a[0], &bx[1], &bx[0]);
    cvm__two_diff(b[1], a[1], &by[1], &by[0]);
    cvm__two_diff(c[0], a[0], &cx[1], &cx[0]);
    cvm__two_diff(c[1], a[1], &cy[1], &cy[0]);
    cvm__two_diff(wa, wb, &wab[1], &wab[0]);
    cvm__two_diff(wa, wc, &wac[1], &wac[0]);
    nbb = dot2(bx, by, bx, by, bb);
    ncc = dot2(cx, cy, cx, cy, cc);
    nbc = dot2(bx, by, cx, cy, bc);
    nbeb = cvm__fast_expansion_sum_zeroelim(nbb, bb, 2, wab, betab);
    nbec = cvm__fast_expansion_sum_zeroelim(ncc, cc, 2, wac, betac);
    n1 = mul(nbb, bb, nbec, betac, t1, tmp, acc);
    n2 = mul(nbc, bc, nbeb, betab, t2, tmp, acc);
    for (i = 0; i < n2; i++)
        t2[i] = -t2[i];
    n = cvm__fast_expansion_sum_zeroelim(n1, t1, n2, t2, det);
    return sign_of(n, det);
}

int cvm__power_side2d(const double *a, const double *b, const double *c, double wa, double wb,
                      double wc)
{
    double m = 0.0, pa[2], pb[2], pc[2], bx, by, cx, cy, bb, cc, bc, betab, betac, det, perm;
    int i, k;
    for (i = 0; i < 2; i++) {
        m = cvm__maxabs(m, a[i]);
        m = cvm__maxabs(m, b[i]);
        m = cvm__maxabs(m, c[i]);
    }
    m = cvm__maxabs(m, sqrt(fabs(wa)));
    m = cvm__maxabs(m, sqrt(fabs(wb)));
    m = cvm__maxabs(m, sqrt(fabs(wc)));
    k = cvm__rescale_exponent(m);
    if (k) { /* exact power-of-two scaling keeps every sign */
        for (i = 0; i < 2; i++) {
            pa[i] = ldexp(a[i], k);
            pb[i] = ldexp(b[i], k);
            pc[i] = ldexp(c[i], k);
        }
        a = pa;
        b = pb;
        c = pc;
        wa = ldexp(wa, 2 * k);
        wb = ldexp(wb, 2 * k);
        wc = ldexp(wc, 2 * k);
    }
    /* Filter. With u = 2^-53, every computed quantity below is within about
     * 11 u * perm of its exact value (|B|^2, B.C: 4 u relative to their
     * absolute sums; beta: 5 u of |B|^2 + |wa| + |wb|; products and the final
     * difference add 1 u each), so 16 u * perm is a safe bound. */
    bx = b[0] - a[0];
    by = b[1] - a[1];
    cx = c[0] - a[0];
    cy = c[1] - a[1];
    bb = bx * bx + by * by;
    cc = cx * cx + cy * cy;
    bc = bx * cx + by * cy;
    betab = bb + (wa - wb);
    betac = cc + (wa - wc);
    det = bb * betac - bc * betab;
    perm = bb * (cc + fabs(wa) + fabs(wc)) + (fabs(bx * cx) + fabs(by * cy)) * (bb + fabs(wa) + fabs(wb));
    if (isfinite(det) && isfinite(perm) && fabs(det) > (16.0 + 1024.0 * CVM__EPS) * CVM__EPS * perm + 0x1p-1020)
        return det > 0 ? 1 : -1;
    return exact_side(a, b, c, wa, wb, wc);
}
