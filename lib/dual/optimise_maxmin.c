/* optimise_maxmin.c - the position solver of the dual optimiser's max-min-angle phase: Freitag's active-set ascent on the sines of the star's angles. */
#include <math.h>

#include "optimise.h"
#include "geom/geom_internal.h"

/* Active-set iterations per solve, step halvings per line search, and the
 * tolerance within which a sine counts as active (Freitag, Jones, Plassmann
 * 1995: the non-smooth max-min problem is solved by steepest ascent along the
 * smallest-norm point of the convex hull of the active gradients). */
#define ITERS 12
#define HALVINGS 10
#define ACTIVE_TOL 1e-6
#define MAXF (3 * CVM__DOPT_MM_MAXSTAR)

/* Sines of the angles of the star's domain triangles with v at p and their
 * gradients in the scaled degrees of freedom of the position (1 with ndof 2,
 * 2 with ndof 3) into f and g (nd per function); their number, or -1 when a
 * domain triangle is not counter-clockwise in plain doubles. *lmin: shortest
 * edge at v. */
static int sines(const cvm__dopt_local *L, const double *p, double *f, double *g, double *lmin)
{
    const cvm__tri2 *T = L->T;
    int nd = L->ndof == 3 ? 2 : 1, n = 0;
    size_t k;
    *lmin = HUGE_VAL;
    for (k = 0; k < L->nstar; k++) {
        int32_t t = L->star[k];
        const int32_t *tv = T->tv + 3 * (size_t)t;
        int i, j;
        const double *a, *b;
        double la2, lb2, la, lb, lab, ar, s[3], gp[6], ga0, ga1, da0, da1, db0, db1;
        if (!cvm__tri2_in_domain(T, t))
            continue;
        i = tv[0] == L->v ? 0 : tv[1] == L->v ? 1 : 2;
        a = T->xy + 2 * (size_t)tv[(i + 1) % 3];
        b = T->xy + 2 * (size_t)tv[(i + 2) % 3];
        la2 = (a[0] - p[0]) * (a[0] - p[0]) + (a[1] - p[1]) * (a[1] - p[1]);
        lb2 = (b[0] - p[0]) * (b[0] - p[0]) + (b[1] - p[1]) * (b[1] - p[1]);
        la = sqrt(la2);
        lb = sqrt(lb2);
        lab = hypot(b[0] - a[0], b[1] - a[1]);
        ar = (a[0] - p[0]) * (b[1] - p[1]) - (a[1] - p[1]) * (b[0] - p[0]);
        if (!(ar > 0) || !(la > 0) || !(lb > 0) || !(lab > 0))
            return -1;
        *lmin = la < *lmin ? la : *lmin;
        *lmin = lb < *lmin ? lb : *lmin;
        s[0] = ar / (la * lb);  /* at v */
        s[1] = ar / (la * lab); /* at a */
        s[2] = ar / (lb * lab); /* at b */
        /* d(ar)/dp = (a1 - b1, b0 - a0); d|p - a|/dp = (p - a) / |p - a| */
        ga0 = (a[1] - b[1]) / ar;
        ga1 = (b[0] - a[0]) / ar;
        da0 = (p[0] - a[0]) / la2;
        da1 = (p[1] - a[1]) / la2;
        db0 = (p[0] - b[0]) / lb2;
        db1 = (p[1] - b[1]) / lb2;
        gp[0] = s[0] * (ga0 - da0 - db0);
        gp[1] = s[0] * (ga1 - da1 - db1);
        gp[2] = s[1] * (ga0 - da0);
        gp[3] = s[1] * (ga1 - da1);
        gp[4] = s[2] * (ga0 - db0);
        gp[5] = s[2] * (ga1 - db1);
        for (j = 0; j < 3; j++) {
            f[n] = s[j];
            if (nd == 2) {
                g[2 * n] = gp[2 * j] * L->h;
                g[2 * n + 1] = gp[2 * j + 1] * L->h;
            } else {
                g[n] = (gp[2 * j] * L->dir[0] + gp[2 * j + 1] * L->dir[1]) * L->h;
            }
            n++;
        }
    }
    return n;
}

void cvm__dopt_maxmin_active(cvm__dopt_local *L, double f0, double *u, double *fout)
{
    double f[MAXF], g[2 * MAXF], f1[MAXF], g1[2 * MAXF], p[2], w, lmin, lmin1, fm, fu = f0;
    int nd = L->ndof == 3 ? 2 : 1, n, it, q;
    size_t act[MAXF];
    double x[CVM__DOPT_MAXDOF] = {0};
    for (q = 0; q < CVM__DOPT_MAXDOF; q++)
        u[q] = 0;
    *fout = f0;
    if (L->ndof < 2 || L->nstar > CVM__DOPT_MM_MAXSTAR || !(f0 < HUGE_VAL))
        return;
    cvm__dopt_point(L, x, p, &w);
    n = sines(L, p, f, g, &lmin);
    if (n <= 0)
        return;
    for (it = 0; it < ITERS; it++) {
        double d[2] = {0, 0}, dd = 0, alpha = HUGE_VAL, amax, y[CVM__DOPT_MAXDOF], fy = HUGE_VAL, m1 = 2;
        int h, ok = 0, k;
        size_t na = 0;
        fm = 2;
        for (k = 0; k < n; k++)
            fm = f[k] < fm ? f[k] : fm;
        for (k = 0; k < n; k++)
            if (f[k] <= fm + ACTIVE_TOL)
                act[na++] = (size_t)k;
        if (!cvm__minnorm_hull(g, nd, act, na, d))
            break;
        for (q = 0; q < nd; q++)
            dd += d[q] * d[q];
        /* the first step at which an inactive sine meets the active ones, to first order */
        for (k = 0; k < n; k++) {
            double gd = 0;
            for (q = 0; q < nd; q++)
                gd += g[nd * k + q] * d[q];
            if (f[k] > fm + ACTIVE_TOL && gd < dd) {
                double a = (f[k] - fm) / (dd - gd);
                alpha = a < alpha ? a : alpha;
            }
        }
        amax = 0.25 * lmin / L->h / sqrt(dd); /* at most a quarter of the shortest spoke */
        if (!(alpha <= amax))
            alpha = amax;
        for (h = 0; h < HALVINGS; h++, alpha *= 0.5) {
            for (q = 0; q < CVM__DOPT_MAXDOF; q++)
                y[q] = x[q];
            for (q = 0; q < nd; q++)
                y[q] += alpha * d[q];
            cvm__dopt_point(L, y, p, &w);
            if (sines(L, p, f1, g1, &lmin1) != n)
                continue;
            for (m1 = 2, k = 0; k < n; k++)
                m1 = f1[k] < m1 ? f1[k] : m1;
            if (!(m1 > fm + 1e-12))
                continue;
            fy = cvm__dopt_eval(L, y); /* the exact tests and the constraints */
            if (fy < fu) {
                ok = 1;
                break;
            }
        }
        if (!ok)
            break;
        for (q = 0; q < CVM__DOPT_MAXDOF; q++)
            x[q] = y[q];
        for (k = 0; k < n; k++)
            f[k] = f1[k];
        for (k = 0; k < nd * n; k++)
            g[k] = g1[k];
        lmin = lmin1;
        fu = fy;
        if (m1 - fm < 1e-6 * fm)
            break;
    }
    for (q = 0; q < CVM__DOPT_MAXDOF; q++)
        u[q] = x[q];
    *fout = fu;
}
