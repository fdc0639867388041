/* measure3.c - volume, dihedral angles, power centre and radius-edge ratio of a tetrahedron. */
#include <math.h>
#include <stddef.h>

#include "geom/measure.h"
#include "geom/measure3.h"

static void sub(const double *a, const double *b, double *o)
{
    o[0] = a[0] - b[0];
    o[1] = a[1] - b[1];
    o[2] = a[2] - b[2];
}

static void cross(const double *u, const double *v, double *o)
{
    o[0] = u[1] * v[2] - u[2] * v[1];
    o[1] = u[2] * v[0] - u[0] * v[2];
    o[2] = u[0] * v[1] - u[1] * v[0];
}

static double dot(const double *u, const double *v)
{
    return u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
}

double cvm__tet_volume(const double *a, const double *b, const double *c, const double *d)
{
    /* orient3d's sign: det[a - d; b - d; c - d] */
    double u[3], v[3], w[3], x[3];
    sub(a, d, u);
    sub(b, d, v);
    sub(c, d, w);
    cross(v, w, x);
    return dot(u, x) / 6.0;
}

/* Dihedral angle at edge pq of the tetrahedron pqrs: the angle between the
 * faces pqr and pqs, measured inside. */
static double dihedral(const double *p, const double *q, const double *r, const double *s)
{
    double e[3], u[3], v[3], nu[3], nv[3], c, sn, m[3];
    sub(q, p, e);
    sub(r, p, u);
    sub(s, p, v);
    cross(e, u, nu);
    cross(e, v, nv);
    c = dot(nu, nv);
    cross(nu, nv, m);
    sn = sqrt(dot(m, m));
    if (c == 0 && sn == 0)
        return 0;
    return atan2(sn, c) * (180.0 / CVM__PI);
}

void cvm__tet_dihedrals_deg(const double *a, const double *b, const double *c, const double *d,
                            double out[6])
{
    const double *P[4];
    static const int e[6][4] = {{0, 1, 2, 3}, {0, 2, 1, 3}, {0, 3, 1, 2},
                                {1, 2, 0, 3}, {1, 3, 0, 2}, {2, 3, 0, 1}};
    int k;
    P[0] = a;
    P[1] = b;
    P[2] = c;
    P[3] = d;
    for (k = 0; k < 6; k++)
        out[k] = dihedral(P[e[k][0]], P[e[k][1]], P[e[k][2]], P[e[k][3]]);
}

void cvm__tet_dihedral_range_deg(const double *a, const double *b, const double *c,
                                 const double *d, double *lo, double *hi)
{
    double t[6];
    int k;
    cvm__tet_dihedrals_deg(a, b, c, d, t);
    *lo = 180;
    *hi = 0;
    for (k = 0; k < 6; k++) {
        if (t[k] < *lo)
            *lo = t[k];
        if (t[k] > *hi)
            *hi = t[k];
    }
}

int cvm__tet_power_centre(const double *a, const double *b, const double *c, const double *d,
                          const double *w, double *o)
{
    /* 2 (p_i - a) . x = |p_i - a|^2 - (w_i - w_a) for x = o - a, i = b, c, d (Cramer) */
    double u[3], v[3], t[3], r[3], uv[3], vt[3], tu[3], det;
    int k;
    sub(b, a, u);
    sub(c, a, v);
    sub(d, a, t);
    r[0] = dot(u, u) - (w ? w[1] - w[0] : 0);
    r[1] = dot(v, v) - (w ? w[2] - w[0] : 0);
    r[2] = dot(t, t) - (w ? w[3] - w[0] : 0);
    cross(u, v, uv);
    cross(v, t, vt);
    cross(t, u, tu);
    det = 2 * dot(u, vt);
    if (det == 0 || !isfinite(det))
        return -1;
    for (k = 0; k < 3; k++)
        o[k] = a[k] + (r[0] * vt[k] + r[1] * tu[k] + r[2] * uv[k]) / det;
    return 0;
}

double cvm__tet_radius_edge(const double *a, const double *b, const double *c, const double *d)
{
    const double *P[4];
    double o[3], lmin = INFINITY;
    int i, j;
    P[0] = a;
    P[1] = b;
    P[2] = c;
    P[3] = d;
    if (cvm__tet_power_centre(a, b, c, d, NULL, o))
        return INFINITY;
    for (i = 0; i < 4; i++)
        for (j = i + 1; j < 4; j++) {
            double e[3];
            sub(P[i], P[j], e);
            if (dot(e, e) < lmin)
                lmin = dot(e, e);
        }
    {
        double r[3];
        sub(o, a, r);
        return sqrt(dot(r, r) / lmin);
    }
}

void cvm__tri3_circle(const double *a, const double *b, const double *c, double *c_out,
                      double *r2, double *n)
{
    double u[3], v[3], w[3], vw[3], wu[3], uu = 0, vv = 0, ww = 0, nn;
    int k;
    for (k = 0; k < 3; k++) {
        u[k] = b[k] - a[k];
        v[k] = c[k] - a[k];
    }
    w[0] = u[1] * v[2] - u[2] * v[1];
    w[1] = u[2] * v[0] - u[0] * v[2];
    w[2] = u[0] * v[1] - u[1] * v[0];
    vw[0] = v[1] * w[2] - v[2] * w[1];
    vw[1] = v[2] * w[0] - v[0] * w[2];
    vw[2] = v[0] * w[1] - v[1] * w[0];
    wu[0] = w[1] * u[2] - w[2] * u[1];
    wu[1] = w[2] * u[0] - w[0] * u[2];
    wu[2] = w[0] * u[1] - w[1] * u[0];
    for (k = 0; k < 3; k++) {
        uu += u[k] * u[k];
        vv += v[k] * v[k];
        ww += w[k] * w[k];
    }
    nn = sqrt(ww);
    *r2 = 0;
    for (k = 0; k < 3; k++) {
        double d = (uu * vw[k] + vv * wu[k]) / (2 * ww);
        c_out[k] = a[k] + d;
        *r2 += d * d;
        n[k] = -w[k] / nn;
    }
}
