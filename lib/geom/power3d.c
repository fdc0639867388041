/* power3d.c - exact 3D power (weighted insphere, lifted orient4d) test: filter, then a rescaled exact expansion. */
#include <math.h>

#include "geom/exact_det.h"
#include "geom/expansion.h"
#include "geom/geom_internal.h"

/*
 * det [p.e  plift] over the rows p = a, b, c, d, with p.e = p - e and
 * plift = |p - e|^2 - (wp - we): the 5x5 determinant [x y z |x|^2-w 1] after
 * subtracting row e and 2 e.(p - e) from the lifted column (as in power2d.c).
 *
 * Filter bound: insphere's monomials carry at most 16 rounding factors
 * (Shewchuk's isperrboundA); the weight difference and its subtraction from
 * the squared length add 2, so gamma_18 times the permanent computed with
 * |p - e|^2 + |wp - we| in place of the lift. 20 + 1024 eps leaves room for the
 * eps^2 terms and the rounding of the bound itself.
 *
 * There is no stage B: ties of weighted points are rare outside lattices, and
 * the exact stage, on power-of-two rescaled inputs, decides them.
 */
static const double pow3_errbound_a = (20.0 + 1024.0 * CVM__EPS) * CVM__EPS;

static CVM__NOINLINE double power3d_adapt(const double *a, const double *b, const double *c,
                                          const double *d, const double *e, double wa, double wb,
                                          double wc, double wd, double we)
{
    const double *p[5];
    double s[5][3], w[5], m = 0.0, mw = 0.0;
    int i, j, k;
    p[0] = a, p[1] = b, p[2] = c, p[3] = d, p[4] = e;
    w[0] = wa, w[1] = wb, w[2] = wc, w[3] = wd, w[4] = we;
    for (i = 0; i < 5; i++) {
        mw = cvm__maxabs(mw, w[i]);
        for (j = 0; j < 3; j++)
            m = cvm__maxabs(m, p[i][j]);
    }
    k = cvm__rescale_exponent(cvm__maxabs(m, sqrt(mw)));
    if (k == 0)
        return cvm__power3d_exact(a, b, c, d, e, wa, wb, wc, wd, we);
    for (i = 0; i < 5; i++) {
        for (j = 0; j < 3; j++)
            s[i][j] = ldexp(p[i][j], k);
        w[i] = ldexp(w[i], 2 * k);
    }
    return cvm__unscale(cvm__power3d_exact(s[0], s[1], s[2], s[3], s[4], w[0], w[1], w[2], w[3],
                                           w[4]),
                        5, k);
}

double cvm__power3d(const double *a, const double *b, const double *c, const double *d,
                    const double *e, double wa, double wb, double wc, double wd, double we)
{
    double aex = a[0] - e[0], bex = b[0] - e[0], cex = c[0] - e[0], dex = d[0] - e[0];
    double aey = a[1] - e[1], bey = b[1] - e[1], cey = c[1] - e[1], dey = d[1] - e[1];
    double aez = a[2] - e[2], bez = b[2] - e[2], cez = c[2] - e[2], dez = d[2] - e[2];
    double wae = wa - we, wbe = wb - we, wce = wc - we, wde = wd - we;
    double aexbey = aex * bey, bexaey = bex * aey, bexcey = bex * cey, cexbey = cex * bey;
    double cexdey = cex * dey, dexcey = dex * cey, dexaey = dex * aey, aexdey = aex * dey;
    double aexcey = aex * cey, cexaey = cex * aey, bexdey = bex * dey, dexbey = dex * bey;
    double ab = aexbey - bexaey, bc = bexcey - cexbey, cd = cexdey - dexcey;
    double da = dexaey - aexdey, ac = aexcey - cexaey, bd = bexdey - dexbey;
    double abc = aez * bc - bez * ac + cez * ab;
    double bcd = bez * cd - cez * bd + dez * bc;
    double cda = cez * da + dez * ac + aez * cd;
    double dab = dez * ab + aez * bd + bez * da;
    double asq = aex * aex + aey * aey + aez * aez;
    double bsq = bex * bex + bey * bey + bez * bez;
    double csq = cex * cex + cey * cey + cez * cez;
    double dsq = dex * dex + dey * dey + dez * dez;
    double det = ((dsq - wde) * abc - (csq - wce) * dab) + ((bsq - wbe) * cda - (asq - wae) * bcd);
    double aezp = fabs(aez), bezp = fabs(bez), cezp = fabs(cez), dezp = fabs(dez);
    double abp = fabs(aexbey) + fabs(bexaey), bcp = fabs(bexcey) + fabs(cexbey);
    double cdp = fabs(cexdey) + fabs(dexcey), dap = fabs(dexaey) + fabs(aexdey);
    double acp = fabs(aexcey) + fabs(cexaey), bdp = fabs(bexdey) + fabs(dexbey);
    double permanent = (aezp * bcp + bezp * acp + cezp * abp) * (dsq + fabs(wde))
                       + (dezp * abp + aezp * bdp + bezp * dap) * (csq + fabs(wce))
                       + (cezp * dap + dezp * acp + aezp * cdp) * (bsq + fabs(wbe))
                       + (bezp * cdp + cezp * bdp + dezp * bcp) * (asq + fabs(wae));
    double errbound = pow3_errbound_a * permanent + cvm__filter_floor;
    if (fabs(det) > errbound)
        return det;
    return power3d_adapt(a, b, c, d, e, wa, wb, wc, wd, we);
}

/* The 5x5 determinant [x y z |x|^2-w 1] expanded along the lifted column, as
 * cvm__insphere_exact with the weights; about 140 KB of stack. */
CVM__NOINLINE double cvm__power3d_exact(const double *a, const double *b, const double *c,
                                        const double *d, const double *e, double wa, double wb,
                                        double wc, double wd, double we)
{
    const double *p[5];
    const double *rest[4];
    double w[5], q[96], term[1344], acc[2][6720];
    int i, j, r, qn, tn, n = 0, cur = 0;
    p[0] = a, p[1] = b, p[2] = c, p[3] = d, p[4] = e;
    w[0] = wa, w[1] = wb, w[2] = wc, w[3] = wd, w[4] = we;
    for (i = 0; i < 5; i++) {
        for (j = 0, r = 0; j < 5; j++)
            if (j != i)
                rest[r++] = p[j];
        qn = cvm__orient3d_raw(rest[0], rest[1], rest[2], rest[3], q);
        tn = cvm__lift_scale(qn, q, p[i], 3, w[i], (i % 2 == 0) ? -1.0 : 1.0, term);
        if (i == 0) {
            for (j = 0; j < tn; j++)
                acc[0][j] = term[j];
            n = tn;
        } else {
            n = cvm__fast_expansion_sum_zeroelim(n, acc[cur], tn, term, acc[1 - cur]);
            cur = 1 - cur;
        }
    }
    return acc[cur][n - 1];
}
