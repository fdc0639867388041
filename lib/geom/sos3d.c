/* sos3d.c - Simulation of Simplicity for the 3D lifted tests (insphere, power3d): break exact ties by point index. */
#include <stdint.h>

#include "geom/geom_internal.h"

/*
 * The insphere and power determinants are linear in the lifted coordinate z of
 * each row (it appears in one column only). Lifting point i to z_i + eps_i,
 * eps_i >> eps_j whenever index i > index j, adds sum_i eps_i dDet/dz_i, so on
 * an exact tie the sign is that of the first nonzero derivative in order of
 * decreasing index. dDet/dz_e = -orient3d(a, b, c, d): raising e's lift moves
 * it out of the sphere, and the test is > 0 inside when orient3d(a,b,c,d) > 0.
 * The determinant is alternating in its five rows, so swapping e with each of
 * a..d gives the other four: orient3d of (a, b, c, d) with that point replaced
 * by e. tests/unit/geom/test_sos3d.c checks them against exactly evaluated
 * determinants with hierarchically small weights.
 */
static int sos3d_lift_sign(const double *a, const double *b, const double *c, const double *d,
                           const double *e, int64_t ia, int64_t ib, int64_t ic, int64_t id,
                           int64_t ie)
{
    int64_t idx[5];
    int order[5], i, j, tmp;

    idx[0] = ia, idx[1] = ib, idx[2] = ic, idx[3] = id, idx[4] = ie;
    for (i = 0; i < 5; i++)
        order[i] = i;
    for (i = 1; i < 5; i++) /* insertion sort by decreasing index */
        for (j = i; j > 0 && idx[order[j]] > idx[order[j - 1]]; j--)
            tmp = order[j], order[j] = order[j - 1], order[j - 1] = tmp;
    for (i = 0; i < 5; i++) {
        int k = order[i];
        double deriv;
        if (k == 4) {
            deriv = -cvm__orient3d_inline(a, b, c, d);
        } else {
            const double *q[4];
            q[0] = a, q[1] = b, q[2] = c, q[3] = d;
            q[k] = e;
            deriv = cvm__orient3d_inline(q[0], q[1], q[2], q[3]);
        }
        if (deriv > 0.0)
            return 1;
        if (deriv < 0.0)
            return -1;
    }
    return -1; /* all five coplanar: outside the precondition; e counts as outside */
}

int cvm__insphere_sos(const double *a, const double *b, const double *c, const double *d,
                      const double *e, int64_t ia, int64_t ib, int64_t ic, int64_t id,
                      int64_t ie)
{
    double det = cvm__insphere_inline(a, b, c, d, e);
    if (det > 0.0)
        return 1;
    if (det < 0.0)
        return -1;
    return sos3d_lift_sign(a, b, c, d, e, ia, ib, ic, id, ie);
}

int cvm__power3d_sos(const double *a, const double *b, const double *c, const double *d,
                     const double *e, double wa, double wb, double wc, double wd, double we,
                     int64_t ia, int64_t ib, int64_t ic, int64_t id, int64_t ie)
{
    double det = cvm__power3d(a, b, c, d, e, wa, wb, wc, wd, we);
    if (det > 0.0)
        return 1;
    if (det < 0.0)
        return -1;
    return sos3d_lift_sign(a, b, c, d, e, ia, ib, ic, id, ie);
}
