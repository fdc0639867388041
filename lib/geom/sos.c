/* sos.c - Simulation of Simplicity for the 2D lifted tests: break exact ties by point index. */
#include <stdint.h>

#include "geom/geom_internal.h"

/*
 * The in-circle and power determinants are linear in the lifted coordinate z
 * of each row. Lifting point i to z_i + eps_i, with eps_i infinitesimal and
 * eps_i >> eps_j whenever index i > index j, adds sum_i eps_i * dDet/dz_i, so
 * on an exact tie the sign is that of the first nonzero derivative in order of
 * decreasing index. From the 4x4 form [x y z 1] expanded along the z column:
 *   dDet/dz_a = orient2d(d, b, c)    dDet/dz_b = orient2d(a, d, c)
 *   dDet/dz_c = orient2d(a, b, d)    dDet/dz_d = -orient2d(a, b, c)
 * i.e. for a, b, c: orient2d of (a, b, c) with that point replaced by d. This
 * is the sign of the perturbed determinant for any orientation of a, b, c, so
 * the result is alternating under every permutation of the four (point, index)
 * pairs. tests/unit/geom/test_sos.c checks the derivatives against exact
 * integer determinants.
 */
static int sos_lift_sign(const double *a, const double *b, const double *c, const double *d,
                         int64_t ia, int64_t ib, int64_t ic, int64_t id)
{
    int64_t idx[4];
    int order[4], i, j, tmp;

    idx[0] = ia, idx[1] = ib, idx[2] = ic, idx[3] = id;
    for (i = 0; i < 4; i++)
        order[i] = i;
    for (i = 1; i < 4; i++) /* insertion sort by decreasing index */
        for (j = i; j > 0 && idx[order[j]] > idx[order[j - 1]]; j--)
            tmp = order[j], order[j] = order[j - 1], order[j - 1] = tmp;
    for (i = 0; i < 4; i++) {
        int k = order[i];
        double deriv;
        if (k == 3) {
            deriv = -cvm__orient2d(a, b, c);
        } else {
            const double *q[3];
            q[0] = a, q[1] = b, q[2] = c;
            q[k] = d;
            deriv = cvm__orient2d(q[0], q[1], q[2]);
        }
        if (deriv > 0.0)
            return 1;
        if (deriv < 0.0)
            return -1;
    }
    return -1; /* all four collinear: outside the precondition; d counts as outside */
}

int cvm__incircle_sos(const double *a, const double *b, const double *c, const double *d,
                      int64_t ia, int64_t ib, int64_t ic, int64_t id)
{
    double det = cvm__incircle_inline(a, b, c, d);
    if (det > 0.0)
        return 1;
    if (det < 0.0)
        return -1;
    return sos_lift_sign(a, b, c, d, ia, ib, ic, id);
}

int cvm__power2d_sos(const double *a, const double *b, const double *c, const double *d,
                     double wa, double wb, double wc, double wd,
                     int64_t ia, int64_t ib, int64_t ic, int64_t id)
{
    double det = cvm__power2d(a, b, c, d, wa, wb, wc, wd);
    if (det > 0.0)
        return 1;
    if (det < 0.0)
        return -1;
    return sos_lift_sign(a, b, c, d, ia, ib, ic, id);
}
