/* orient3d.c - exact 3D orientation: filter, exact stage B, then an exact expansion. */
#include <math.h>

#include "geom/exact_det.h"
#include "geom/expansion.h"
#include "geom/geom_internal.h"

/* Shewchuk's o3derrboundB (A is cvm__o3d_errbound_a in geom_internal.h). */
static const double o3d_errbound_b = (3.0 + 28.0 * CVM__EPS) * CVM__EPS;

/* Stage B (det [a-d; b-d; c-d] of the rounded differences), then the exact
 * expansion, on inputs already in the safe range. */
static double orient3d_stages(const double *a, const double *b, const double *c, const double *d)
{
    double adx = a[0] - d[0], bdx = b[0] - d[0], cdx = c[0] - d[0];
    double ady = a[1] - d[1], bdy = b[1] - d[1], cdy = c[1] - d[1];
    double adz = a[2] - d[2], bdz = b[2] - d[2], cdz = c[2] - d[2];
    double m[4], t[3][8], ab[16], fin[24], permanent, det, errbound;
    int n[3], mn, abn, fn, i;

    mn = cvm__cross_zeroelim(bdx, cdy, cdx, bdy, m);
    n[0] = cvm__scale_expansion_zeroelim(mn, m, adz, t[0]);
    mn = cvm__cross_zeroelim(cdx, ady, adx, cdy, m);
    n[1] = cvm__scale_expansion_zeroelim(mn, m, bdz, t[1]);
    mn = cvm__cross_zeroelim(adx, bdy, bdx, ady, m);
    n[2] = cvm__scale_expansion_zeroelim(mn, m, cdz, t[2]);
    abn = cvm__fast_expansion_sum_zeroelim(n[0], t[0], n[1], t[1], ab);
    fn = cvm__fast_expansion_sum_zeroelim(abn, ab, n[2], t[2], fin);
    det = cvm__estimate(fn, fin);
    permanent = (fabs(bdx * cdy) + fabs(cdx * bdy)) * fabs(adz)
                + (fabs(cdx * ady) + fabs(adx * cdy)) * fabs(bdz)
                + (fabs(adx * bdy) + fabs(bdx * ady)) * fabs(cdz);
    errbound = o3d_errbound_b * permanent;
    if (det >= errbound || -det >= errbound)
        return det;
    for (i = 0; i < 3; i++) {
        if (cvm__two_diff_tail(a[i], d[i], a[i] - d[i]) != 0.0
            || cvm__two_diff_tail(b[i], d[i], b[i] - d[i]) != 0.0
            || cvm__two_diff_tail(c[i], d[i], c[i] - d[i]) != 0.0)
            return cvm__orient3d_exact(a, b, c, d);
    }
    return det; /* every difference was exact, so B was the exact value */
}

CVM__NOINLINE double cvm__orient3d_adapt(const double *a, const double *b, const double *c,
                                         const double *d)
{
    const double *p[4];
    double s[4][3], m = 0.0;
    int i, j, k;
    p[0] = a, p[1] = b, p[2] = c, p[3] = d;
    for (i = 0; i < 4; i++)
        for (j = 0; j < 3; j++)
            m = cvm__maxabs(m, p[i][j]);
    k = cvm__rescale_exponent(m);
    if (k == 0)
        return orient3d_stages(a, b, c, d);
    for (i = 0; i < 4; i++)
        for (j = 0; j < 3; j++)
            s[i][j] = ldexp(p[i][j], k);
    return cvm__unscale(orient3d_stages(s[0], s[1], s[2], s[3]), 3, k);
}

double cvm__orient3d(const double *a, const double *b, const double *c, const double *d)
{
    return cvm__orient3d_inline(a, b, c, d);
}

CVM__NOINLINE double cvm__orient3d_exact(const double *a, const double *b, const double *c,
                                         const double *d)
{
    double h[96];
    int n = cvm__orient3d_raw(a, b, c, d, h);
    return h[n - 1];
}
