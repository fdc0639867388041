/* intdet.c - the predicates' determinants in plain int64 for small-integer coordinates. */
#include <stdint.h>

#include "geom/geom_tests.h"

int64_t intdet_orient2d(const double *a, const double *b, const double *c)
{
    int64_t acx = (int64_t)a[0] - (int64_t)c[0], acy = (int64_t)a[1] - (int64_t)c[1];
    int64_t bcx = (int64_t)b[0] - (int64_t)c[0], bcy = (int64_t)b[1] - (int64_t)c[1];
    return acx * bcy - acy * bcx;
}

int64_t intdet_power2d(const double *a, const double *b, const double *c, const double *d,
                       double wa, double wb, double wc, double wd)
{
    const double *p[3];
    double w[3];
    int64_t x[3], y[3], l[3];
    int i;
    p[0] = a, p[1] = b, p[2] = c;
    w[0] = wa, w[1] = wb, w[2] = wc;
    for (i = 0; i < 3; i++) {
        x[i] = (int64_t)p[i][0] - (int64_t)d[0];
        y[i] = (int64_t)p[i][1] - (int64_t)d[1];
        l[i] = x[i] * x[i] + y[i] * y[i] - ((int64_t)w[i] - (int64_t)wd);
    }
    return l[0] * (x[1] * y[2] - x[2] * y[1]) + l[1] * (x[2] * y[0] - x[0] * y[2])
           + l[2] * (x[0] * y[1] - x[1] * y[0]);
}

int64_t intdet_incircle(const double *a, const double *b, const double *c, const double *d)
{
    return intdet_power2d(a, b, c, d, 0.0, 0.0, 0.0, 0.0);
}

static int64_t det3(const int64_t *r0, const int64_t *r1, const int64_t *r2)
{
    return r0[0] * (r1[1] * r2[2] - r1[2] * r2[1]) - r0[1] * (r1[0] * r2[2] - r1[2] * r2[0])
           + r0[2] * (r1[0] * r2[1] - r1[1] * r2[0]);
}

int64_t intdet_orient3d(const double *a, const double *b, const double *c, const double *d)
{
    int64_t r[3][3];
    int j;
    for (j = 0; j < 3; j++) {
        r[0][j] = (int64_t)a[j] - (int64_t)d[j];
        r[1][j] = (int64_t)b[j] - (int64_t)d[j];
        r[2][j] = (int64_t)c[j] - (int64_t)d[j];
    }
    return det3(r[0], r[1], r[2]);
}

/* det [p - e, |p - e|^2] for p = a, b, c, d, expanded along the lifted column. */
int64_t intdet_insphere(const double *a, const double *b, const double *c, const double *d,
                        const double *e)
{
    const double *p[4];
    int64_t r[4][3], lift[4], det = 0;
    int i, j, k, m;
    p[0] = a, p[1] = b, p[2] = c, p[3] = d;
    for (i = 0; i < 4; i++) {
        lift[i] = 0;
        for (j = 0; j < 3; j++) {
            r[i][j] = (int64_t)p[i][j] - (int64_t)e[j];
            lift[i] += r[i][j] * r[i][j];
        }
    }
    for (i = 0; i < 4; i++) {
        const int64_t *rows[3];
        for (k = 0, m = 0; k < 4; k++)
            if (k != i)
                rows[m++] = r[k];
        /* cofactor sign of (i, 3) in a 4x4: (-1)^(i + 3) */
        det += ((i % 2 == 0) ? -1 : 1) * lift[i] * det3(rows[0], rows[1], rows[2]);
    }
    return det;
}
