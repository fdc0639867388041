/* exact_det.c - expansion-valued determinants of raw coordinates shared by the exact stages. */
#include <string.h>

#include "geom/exact_det.h"
#include "geom/expansion.h"

/* Expanding along the column of ones: m(p,q) + m(q,r) + m(r,p), m(p,q) = px qy - qx py. */
int cvm__orient2d_raw(const double *p, const double *q, const double *r, double *h)
{
    double pq[4], qr[4], rp[4], s[8];
    int npq, nqr, nrp, n;
    npq = cvm__cross_zeroelim(p[0], q[1], q[0], p[1], pq);
    nqr = cvm__cross_zeroelim(q[0], r[1], r[0], q[1], qr);
    nrp = cvm__cross_zeroelim(r[0], p[1], p[0], r[1], rp);
    n = cvm__fast_expansion_sum_zeroelim(npq, pq, nqr, qr, s);
    return cvm__fast_expansion_sum_zeroelim(n, s, nrp, rp, h);
}

/* Expanding along z: pz T(q,r,s) - qz T(p,r,s) + rz T(p,q,s) - sz T(p,q,r),
 * T the raw orient2d of the xy projections. */
int cvm__orient3d_raw(const double *p, const double *q, const double *r, const double *s,
                      double *h)
{
    double t[12], u[4][24], v[2][48];
    int tn, n[4], m0, m1;
    tn = cvm__orient2d_raw(q, r, s, t);
    n[0] = cvm__scale_expansion_zeroelim(tn, t, p[2], u[0]);
    tn = cvm__orient2d_raw(p, r, s, t);
    n[1] = cvm__scale_expansion_zeroelim(tn, t, -q[2], u[1]);
    tn = cvm__orient2d_raw(p, q, s, t);
    n[2] = cvm__scale_expansion_zeroelim(tn, t, r[2], u[2]);
    tn = cvm__orient2d_raw(p, q, r, t);
    n[3] = cvm__scale_expansion_zeroelim(tn, t, -s[2], u[3]);
    m0 = cvm__fast_expansion_sum_zeroelim(n[0], u[0], n[1], u[1], v[0]);
    m1 = cvm__fast_expansion_sum_zeroelim(n[2], u[2], n[3], u[3], v[1]);
    return cvm__fast_expansion_sum_zeroelim(m0, v[0], m1, v[1], h);
}

int cvm__lift_scale(int tlen, const double *t, const double *p, int dim, double w, double sign,
                    double *h)
{
    double tx[192], txx[384], acc[2][1152];
    int j, l1, l2, n = 0, cur = 0;

    for (j = 0; j < dim; j++) {
        l1 = cvm__scale_expansion_zeroelim(tlen, t, sign * p[j], tx);
        l2 = cvm__scale_expansion_zeroelim(l1, tx, p[j], txx);
        if (j == 0) {
            memcpy(acc[0], txx, (size_t)l2 * sizeof(double));
            n = l2;
        } else {
            n = cvm__fast_expansion_sum_zeroelim(n, acc[cur], l2, txx, acc[1 - cur]);
            cur = 1 - cur;
        }
    }
    if (w != 0.0) {
        l1 = cvm__scale_expansion_zeroelim(tlen, t, -sign * w, tx);
        return cvm__fast_expansion_sum_zeroelim(n, acc[cur], l1, tx, h);
    }
    memcpy(h, acc[cur], (size_t)n * sizeof(double));
    return n;
}
