/* optimise_objective.c - the local objective of the dual optimiser: a smooth penalty on one vertex's star. */
#include <math.h>

#include "optimise.h"
#include "geom/geom_internal.h"

/* Weight of the centroid term beside the containment penalty, and of the
 * weight regulariser (keeps weights near 0 where nothing asks for them). */
#define CONTAIN_W 10.0
#define CENTROID_W 0.05
#define ANGLE_W 1.0
#define WEIGHT_W 1e-4

void cvm__dopt_point(const cvm__dopt_local *L, const double *u, double *p, double *w)
{
    switch (L->ndof) {
    case 3:
        p[0] = L->p0[0] + u[0] * L->h;
        p[1] = L->p0[1] + u[1] * L->h;
        *w = L->w0 + u[2] * L->h * L->h;
        break;
    case 2:
        p[0] = L->p0[0] + u[0] * L->h * L->dir[0];
        p[1] = L->p0[1] + u[0] * L->h * L->dir[1];
        *w = L->w0 + u[1] * L->h * L->h;
        break;
    default:
        p[0] = L->p0[0];
        p[1] = L->p0[1];
        *w = L->w0 + u[0] * L->h * L->h;
        break;
    }
}

static double cross(const double *o, const double *a, const double *b)
{
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

static double sq(double x)
{
    return x * x;
}

/* Corners of star triangle t with v at candidate p (weight wv): q[k], wk[k];
 * returns the corner index of v. */
static int corners(const cvm__dopt_local *L, int32_t t, const double *p, double wv,
                   const double **q, double *wk)
{
    const int32_t *tv = L->T->tv + 3 * (size_t)t;
    int k, iv = 0;
    for (k = 0; k < 3; k++) {
        if (tv[k] == L->v) {
            q[k] = p;
            wk[k] = wv;
            iv = k;
        } else {
            q[k] = L->T->xy + 2 * (size_t)tv[k];
            wk[k] = L->T->w ? L->T->w[tv[k]] : 0.0;
        }
    }
    return iv;
}

static double min_sin2(const double *const *q)
{
    double l2[3], c = cross(q[0], q[1], q[2]), m = HUGE_VAL;
    int k;
    for (k = 0; k < 3; k++)
        l2[k] = sq(q[(k + 1) % 3][0] - q[(k + 2) % 3][0]) + sq(q[(k + 1) % 3][1] - q[(k + 2) % 3][1]);
    for (k = 0; k < 3; k++) {
        /* angle at corner k lies between the sides (k+1) and (k+2) */
        double s = c * c / (l2[(k + 1) % 3] * l2[(k + 2) % 3]);
        m = s < m ? s : m;
    }
    return c > 0 ? m : 0.0;
}

double cvm__dopt_star_min_sin2(const cvm__dopt_local *L)
{
    const double *q[3];
    double wk[3], m = 1.0;
    size_t i;
    for (i = 0; i < L->nstar; i++) {
        int32_t t = L->star[i];
        double s;
        if (!cvm__tri2_in_domain(L->T, t))
            continue;
        corners(L, t, L->p0, L->w0, q, wk);
        s = min_sin2(q);
        m = s < m ? s : m;
    }
    return m;
}

double cvm__dopt_eval(cvm__dopt_local *L, const double *u)
{
    const cvm__tri2 *T = L->T;
    double p[2], wv, f = 0.0, cell = 0.0;
    size_t i;
    L->evals++;
    cvm__dopt_point(L, u, p, &wv);
    if (!isfinite(p[0]) || !isfinite(p[1]) || !isfinite(wv))
        return HUGE_VAL;
    for (i = 0; i < L->nstar; i++) {
        int32_t t = L->star[i];
        const int32_t *tv = T->tv + 3 * (size_t)t;
        const double *q[3];
        double wk[3], V[2], C[2], l2 = 0.0, pen = 0.0, prio = 1.0, s2;
        int k, iv;
        if (cvm__tri2_is_ghost(T, t))
            continue;
        iv = corners(L, t, p, wv, q, wk);
        if (cvm__orient2d(q[0], q[1], q[2]) <= 0)
            return HUGE_VAL;
        if (T->tf[t] & CVM__TF_OUT)
            continue;
        s2 = min_sin2(q);
        if (s2 < L->sin2_bound)
            return HUGE_VAL;
        if (s2 < L->sin2_target)
            f += ANGLE_W * sq(1.0 - s2 / L->sin2_target);
        cvm__power_vertex2d(q[0], q[1], q[2], wk[0], wk[1], wk[2], V);
        if (!isfinite(V[0]) || !isfinite(V[1]))
            return HUGE_VAL;
        for (k = 0; k < 3; k++) {
            const double *a = q[(k + 1) % 3], *b = q[(k + 2) % 3];
            double e2 = sq(b[0] - a[0]) + sq(b[1] - a[1]), len = sqrt(e2);
            double s = cross(a, b, V) / len; /* > 0: V on the inner side of edge k */
            double d = L->margin * len - s;
            l2 += e2;
            if (d > 0)
                pen += d * d;
            if (L->vbnd[tv[k]])
                prio = 2.0;
        }
        l2 /= 3.0;
        C[0] = (q[0][0] + q[1][0] + q[2][0]) / 3.0;
        C[1] = (q[0][1] + q[1][1] + q[2][1]) / 3.0;
        f += prio * (CONTAIN_W * pen + CENTROID_W * (sq(C[0] - V[0]) + sq(C[1] - V[1]))) / l2;
        {
            /* v's share of its power cell in this triangle: the kites on its two edges */
            const double *a = q[(iv + 1) % 3], *b = q[(iv + 2) % 3];
            double Ma[2], Mb[2];
            cvm__power_foot2d(p, a, wv, wk[(iv + 1) % 3], Ma);
            cvm__power_foot2d(b, p, wk[(iv + 2) % 3], wv, Mb);
            cell += 0.5 * (cross(p, Ma, V) + cross(p, V, Mb));
        }
    }
    if (!(cell > 0))
        return HUGE_VAL;
    return f + WEIGHT_W * sq(wv / (L->h * L->h));
}
