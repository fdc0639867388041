/* optimise_objective.c - the local objective of the dual optimiser: a smooth penalty on one vertex's star. */
#include <math.h>

#include "optimise.h"
#include "geom/geom_internal.h"
#include "geom/measure.h"

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

/* sin^2 of the smallest angle of q[0], q[1], q[2]; 0 unless counter-clockwise. */
static double min_sin2(const double *const *q)
{
    return cvm__cross2(q[0], q[1], q[2]) > 0 ? cvm__min_sin2_corners(q[0], q[1], q[2]) : 0.0;
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
    return cvm__dopt_eval_below(L, u, HUGE_VAL);
}

double cvm__dopt_eval_below(cvm__dopt_local *L, const double *u, double bound)
{
    const cvm__tri2 *T = L->T;
    double p[2], wv, f = 0.0, cell = 0.0;
    size_t i;
    if (L->maxmin)
        return cvm__dopt_eval_maxmin(L, u, NULL);
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
            double s = cvm__cross2(a, b, V) / len; /* > 0: V on the inner side of edge k */
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
        if (f >= bound)
            return f; /* every term is >= 0: the total cannot get below bound */
        {
            /* v's share of its power cell in this triangle: the kites on its two edges */
            const double *a = q[(iv + 1) % 3], *b = q[(iv + 2) % 3];
            double Ma[2], Mb[2];
            cvm__power_foot2d(p, a, wv, wk[(iv + 1) % 3], Ma);
            cvm__power_foot2d(b, p, wk[(iv + 2) % 3], wv, Mb);
            cell += 0.5 * (cvm__cross2(p, Ma, V) + cvm__cross2(p, V, Mb));
        }
    }
    if (!(cell > 0))
        return HUGE_VAL;
    return f + WEIGHT_W * sq(wv / (L->h * L->h));
}

/* Weight of the smallest containment slack beside the smallest sin^2 in the
 * max-min-angle objective: small, so it only breaks ties (about 0.06 degree
 * per 0.1 of slack near 40 degrees). */
#define MM_SLACK_W 0.01

/* Point and weight of vertex x with v at candidate p, wv. */
static const double *vpt(const cvm__dopt_local *L, int32_t x, const double *p, double wv, double *w)
{
    if (x == L->v) {
        *w = wv;
        return p;
    }
    *w = L->T->w ? L->T->w[x] : 0.0;
    return L->T->xy + 2 * (size_t)x;
}

/* 1 when edge j of star triangle t (v at p, wv) passes the test of the
 * regular triangulation's flips (cvm__tri2_make_regular): unconstrained edges
 * between two live real triangles of one domain flag and region must not let
 * the apex across conflict with t (exact power test, symbolic perturbation). */
static int edge_regular(const cvm__dopt_local *L, int32_t t, int j, const double *p, double wv)
{
    const cvm__tri2 *T = L->T;
    size_t h = 3 * (size_t)t + (size_t)j;
    const int32_t *tv = T->tv + 3 * (size_t)t;
    int32_t u, d;
    const double *q[4];
    double w[4];
    int k;
    if (cvm__tri2_edge_seg(T, t, j) >= 0)
        return 1;
    u = T->tn[h] / 3;
    if (cvm__tri2_is_ghost(T, u) || ((T->tf[t] ^ T->tf[u]) & CVM__TF_OUT) || (T->ta && T->ta[t] != T->ta[u]))
        return 1;
    d = T->tv[3 * (size_t)u + (size_t)(T->tn[h] % 3)];
    for (k = 0; k < 3; k++)
        q[k] = vpt(L, tv[k], p, wv, &w[k]);
    q[3] = vpt(L, d, p, wv, &w[3]);
    return cvm__power2d_sos(q[0], q[1], q[2], q[3], w[0], w[1], w[2], w[3], tv[0], tv[1], tv[2], d) <= 0;
}

void cvm__dopt_maxmin_cache(cvm__dopt_local *L)
{
    const cvm__tri2 *T = L->T;
    size_t i, j;
    int k;
    L->vnb_ok = 0;
    if (L->nstar > CVM__DOPT_MM_MAXSTAR)
        return;
    for (i = 0; i < L->nstar; i++) {
        int32_t t = L->star[i];
        if (!cvm__tri2_in_domain(T, t))
            continue;
        for (k = 0; k < 3; k++) {
            int32_t nb = T->tn[3 * (size_t)t + (size_t)k] / 3;
            int in_star = 0;
            if (!cvm__tri2_in_domain(T, nb))
                continue;
            for (j = 0; j < L->nstar && !in_star; j++)
                in_star = L->star[j] == nb;
            if (!in_star)
                cvm__dual_tri_vertex(T, nb, L->vnb + 2 * (3 * i + (size_t)k));
        }
    }
    L->vnb_ok = 1;
}

double cvm__dopt_eval_maxmin(cvm__dopt_local *L, const double *u, double *slack_out)
{
    const cvm__tri2 *T = L->T;
    double p[2], wv, Vs[2 * CVM__DOPT_MM_MAXSTAR], m = 1.0, slack = HUGE_VAL, dual = HUGE_VAL;
    size_t i, n = L->nstar;
    L->evals++;
    if (n > CVM__DOPT_MM_MAXSTAR)
        return HUGE_VAL;
    cvm__dopt_point(L, u, p, &wv);
    if (!isfinite(p[0]) || !isfinite(p[1]) || !isfinite(wv))
        return HUGE_VAL;
    /* orientation, regularity, angles, power vertices and their slack */
    for (i = 0; i < n; i++) {
        int32_t t = L->star[i];
        const double *q[3];
        double wk[3], *V = Vs + 2 * i;
        int k;
        if (cvm__tri2_is_ghost(T, t))
            continue;
        corners(L, t, p, wv, q, wk);
        if (cvm__orient2d(q[0], q[1], q[2]) <= 0)
            return HUGE_VAL;
        for (k = 0; k < 3; k++)
            if (!edge_regular(L, t, k, p, wv))
                return HUGE_VAL;
        if (!cvm__tri2_in_domain(T, t))
            continue;
        {
            double s2 = min_sin2(q);
            m = s2 < m ? s2 : m;
        }
        cvm__power_vertex2d(q[0], q[1], q[2], wk[0], wk[1], wk[2], V);
        if (!isfinite(V[0]) || !isfinite(V[1]))
            return HUGE_VAL;
        for (k = 0; k < 3; k++) {
            const double *a = q[(k + 1) % 3], *b = q[(k + 2) % 3];
            double s = cvm__cross2(a, b, V) / (sq(b[0] - a[0]) + sq(b[1] - a[1]));
            slack = s < slack ? s : slack;
        }
    }
    /* dual edges across the edges of the star's domain triangles */
    for (i = 0; i < n; i++) {
        int32_t t = L->star[i];
        const int32_t *tv = T->tv + 3 * (size_t)t;
        int k;
        if (!cvm__tri2_in_domain(T, t))
            continue;
        for (k = 0; k < 3; k++) {
            int32_t nb = T->tn[3 * (size_t)t + (size_t)k] / 3;
            double Vo[2], e[2], wa, wb;
            const double *Vu = NULL, *a, *b;
            size_t j;
            if (!cvm__tri2_in_domain(T, nb))
                continue;
            for (j = 0; j < n && !Vu; j++)
                if (L->star[j] == nb)
                    Vu = Vs + 2 * j;
            if (!Vu && L->vnb_ok) {
                Vu = L->vnb + 2 * (3 * i + (size_t)k);
            } else if (!Vu) {
                cvm__dual_tri_vertex(T, nb, Vo); /* not in the star: v is no corner of it */
                Vu = Vo;
            }
            a = vpt(L, tv[(k + 1) % 3], p, wv, &wa);
            b = vpt(L, tv[(k + 2) % 3], p, wv, &wb);
            e[0] = hypot(Vs[2 * i] - Vu[0], Vs[2 * i + 1] - Vu[1]);
            e[1] = hypot(b[0] - a[0], b[1] - a[1]);
            if (e[0] < dual * e[1])
                dual = e[0] / e[1];
        }
    }
    if (slack_out) {
        slack_out[0] = slack;
        slack_out[1] = dual;
    } else if (slack < L->slack_bound || dual < L->dual_bound || m < L->mm_m0) {
        return HUGE_VAL;
    }
    return -m - MM_SLACK_W * (slack < 0.5 ? slack : 0.5);
}
