/* metric.c - the metric field of the quad mesher: 2x2 tensor eigen-algebra with derivatives, the
 * factor M = Lambda^(1/2) Q^T, the built-in fields, and the checked evaluation through the sizing. */
#include <math.h>

#include "quad_internal.h"

/* 0/0 and x/0 read as 0: the derivative of an eigen-direction where the gap closes (measure zero). */
static double ratio0(double num, double den)
{
    return (num == 0 || den == 0) ? 0 : num / den;
}

void cvm__eig2_of(cvm__eig2 *e, const double g[3], const double *dg)
{
    double c = g[0] - g[2], s = 2 * g[1], rho = sqrt(c * c + s * s), m = 0.5 * (g[0] + g[2]);
    int k;
    /* cos th and sin th, th = atan2(s, c) / 2 in (-pi/2, pi/2], by the half-angle formulas,
     * each from its better-conditioned side */
    if (rho == 0) {
        e->cs = 1;
        e->sn = 0;
    } else if (c >= 0) {
        e->cs = sqrt(0.5 * (1 + c / rho));
        e->sn = s / (2 * rho * e->cs);
    } else {
        e->sn = copysign(sqrt(0.5 * (1 - c / rho)), s);
        e->cs = s / (2 * rho * e->sn);
    }
    e->lam[0] = m + 0.5 * rho;
    e->lam[1] = m - 0.5 * rho;
    for (k = 0; k < 2; k++) {
        double dc = dg ? dg[3 * k] - dg[3 * k + 2] : 0, ds = dg ? 2 * dg[3 * k + 1] : 0;
        double dm = dg ? 0.5 * (dg[3 * k] + dg[3 * k + 2]) : 0;
        double dr = ratio0(c * dc + s * ds, 2 * rho); /* d(rho / 2) */
        e->dth[k] = ratio0(0.5 * (c * ds - s * dc), rho * rho);
        e->dlam[k] = dm + dr;     /* d lam0 / d x_k */
        e->dlam[2 + k] = dm - dr; /* d lam1 / d x_k */
    }
}

void cvm__eig2_compose(double g[3], double *dg, double cs, double sn, const double mu[2],
                       const double *dmu, const double *dth)
{
    int k;
    g[0] = mu[0] * cs * cs + mu[1] * sn * sn;
    g[1] = (mu[0] - mu[1]) * cs * sn;
    g[2] = mu[0] * sn * sn + mu[1] * cs * cs;
    if (!dg)
        return;
    for (k = 0; k < 2; k++) {
        double d0 = dmu[k], d1 = dmu[2 + k], t = dth[k];
        dg[3 * k] = d0 * cs * cs + d1 * sn * sn + 2 * cs * sn * (mu[1] - mu[0]) * t;
        dg[3 * k + 1] = (d0 - d1) * cs * sn + (mu[0] - mu[1]) * (cs * cs - sn * sn) * t;
        dg[3 * k + 2] = d0 * sn * sn + d1 * cs * cs + 2 * cs * sn * (mu[0] - mu[1]) * t;
    }
}

void cvm__metric_factor(double M[4], double *dM, const double g[3], const double *dg)
{
    cvm__eig2 e;
    double cs, sn, r0, r1;
    int k;
    cvm__eig2_of(&e, g, dg);
    cs = e.cs;
    sn = e.sn;
    r0 = sqrt(e.lam[0]);
    r1 = sqrt(e.lam[1]);
    M[0] = r0 * cs;
    M[1] = r0 * sn;
    M[2] = -r1 * sn;
    M[3] = r1 * cs;
    if (!dM)
        return;
    for (k = 0; k < 2; k++) {
        double a0 = e.dlam[k] / (2 * r0), a1 = e.dlam[2 + k] / (2 * r1), t = e.dth[k];
        dM[4 * k] = a0 * cs - r0 * sn * t;
        dM[4 * k + 1] = a0 * sn + r0 * cs * t;
        dM[4 * k + 2] = -a1 * sn - r1 * cs * t;
        dM[4 * k + 3] = a1 * cs - r1 * sn * t;
    }
}

/* The cosine and sine of half the angle of (c, s) = (g11 - g22, 2 g12), whose length is rho
 * (the eigenvector rotation of a symmetric 2x2 tensor), without atan2; returns 1 / rho (0 when
 * rho is 0: then cs 1, sn 0). */
static double half_angle(double c, double s, double rho, double *cs, double *sn)
{
    double ir;
    if (rho == 0) {
        *cs = 1;
        *sn = 0;
        return 0;
    }
    ir = 1 / rho;
    if (c >= 0) {
        *cs = sqrt(0.5 * (1 + c * ir));
        *sn = 0.5 * s * ir / *cs;
    } else {
        *sn = copysign(sqrt(0.5 * (1 - c * ir)), s);
        *cs = 0.5 * s * ir / *sn;
    }
    return ir;
}

/* cvm__metric_factor() (dM required) with one reciprocal per quantity instead of a division per
 * use: the same M and dM up to rounding. */
static void factor_quick(double M[4], double dM[8], const double g[3], const double dg[6])
{
    double c = g[0] - g[2], s = 2 * g[1], rho = sqrt(c * c + s * s), m = 0.5 * (g[0] + g[2]);
    double cs, sn, r0, r1, h0, h1, ir = 0, ir2;
    int k;
    ir = half_angle(c, s, rho, &cs, &sn);
    ir2 = ir * ir; /* 0 where the gap closes: the derivatives of th read 0 there */
    r0 = sqrt(m + 0.5 * rho);
    r1 = sqrt(m - 0.5 * rho);
    h0 = 0.5 / r0;
    h1 = 0.5 / r1;
    M[0] = r0 * cs;
    M[1] = r0 * sn;
    M[2] = -r1 * sn;
    M[3] = r1 * cs;
    for (k = 0; k < 2; k++) {
        double dc = dg[3 * k] - dg[3 * k + 2], ds = 2 * dg[3 * k + 1];
        double dm = 0.5 * (dg[3 * k] + dg[3 * k + 2]), dr = 0.5 * (c * dc + s * ds) * ir;
        double t = 0.5 * (c * ds - s * dc) * ir2, a0 = (dm + dr) * h0, a1 = (dm - dr) * h1;
        dM[4 * k] = a0 * cs - r0 * sn * t;
        dM[4 * k + 1] = a0 * sn + r0 * cs * t;
        dM[4 * k + 2] = -a1 * sn - r1 * cs * t;
        dM[4 * k + 3] = a1 * cs - r1 * sn * t;
    }
}

/* The eigen-structure of cvm__metric_hessian_abs(): *e the eigen-decomposition of H (its
 * directions are those of g), mu and dmu g's eigenvalues along them and their derivatives. */
static void hessian_abs_eig(cvm__eig2 *ep, double mu[2], double dmu[4], const double H[3],
                            const double *dH, double hmin, double hmax, double aspect)
{
    cvm__eig2 e;
    double h[2], dh[4] = {0, 0, 0, 0};
    int k, m, big, small;
    cvm__eig2_of(&e, H, dH);
    for (k = 0; k < 2; k++) {
        double a = fabs(e.lam[k]), sg = e.lam[k] < 0 ? -1 : 1;
        h[k] = a > 0 ? 1 / sqrt(a) : hmax;
        if (h[k] <= hmin)
            h[k] = hmin;
        else if (h[k] >= hmax)
            h[k] = hmax;
        else
            for (m = 0; m < 2; m++)
                dh[2 * k + m] = -0.5 * sg * e.dlam[2 * k + m] / (a * sqrt(a));
    }
    big = h[0] >= h[1] ? 0 : 1;
    small = 1 - big;
    if (h[big] > aspect * h[small]) {
        h[big] = aspect * h[small];
        for (m = 0; m < 2; m++)
            dh[2 * big + m] = aspect * dh[2 * small + m];
    }
    for (k = 0; k < 2; k++) {
        mu[k] = 1 / (h[k] * h[k]);
        for (m = 0; m < 2; m++)
            dmu[2 * k + m] = -2 * dh[2 * k + m] / (h[k] * h[k] * h[k]);
    }
    *ep = e;
}

void cvm__metric_hessian_abs(double g[3], double *dg, const double H[3], const double *dH,
                             double hmin, double hmax, double aspect)
{
    cvm__eig2 e;
    double mu[2], dmu[4];
    hessian_abs_eig(&e, mu, dmu, H, dH, hmin, hmax, aspect);
    cvm__eig2_compose(g, dH ? dg : NULL, e.cs, e.sn, mu, dmu, e.dth);
}

void cvm__metric_grad_outer(double g[3], double *dg, const double grad[2], const double *H)
{
    double v0 = grad[0], v1 = grad[1];
    int m;
    g[0] = 1 + v0 * v0;
    g[1] = v0 * v1;
    g[2] = 1 + v1 * v1;
    if (!dg || !H)
        return;
    for (m = 0; m < 2; m++) {
        double h0 = H[m], h1 = H[m + 1]; /* column m of the Hessian: d grad / d x_m */
        dg[3 * m] = 2 * v0 * h0;
        dg[3 * m + 1] = h0 * v1 + v0 * h1;
        dg[3 * m + 2] = 2 * v1 * h1;
    }
}

/* The S-shock field: f = 3/4 tanh(z), z = 2 (sin 5y - 3x); its Hessian and third derivatives. */
static void sshock_hessian(double H[3], double dH[6], double x, double y)
{
    double z = 2 * (sin(5 * y) - 3 * x), t = tanh(z), u = 1 - t * t;
    double F1 = 0.75 * u, F2 = -1.5 * t * u, F3 = 0.75 * u * (6 * t * t - 2);
    double zx = -6, zy = 10 * cos(5 * y), zyy = -50 * sin(5 * y), zyyy = -250 * cos(5 * y);
    H[0] = F2 * zx * zx;
    H[1] = F2 * zx * zy;
    H[2] = F2 * zy * zy + F1 * zyy;
    if (!dH)
        return;
    dH[0] = F3 * zx * zx * zx;                          /* f_xxx */
    dH[1] = F3 * zx * zx * zy;                          /* f_xxy */
    dH[2] = F3 * zx * zy * zy + F2 * zx * zyy;          /* f_xyy */
    dH[3] = dH[1];                                      /* d/dy: f_xxy, f_xyy, f_yyy */
    dH[4] = dH[2];
    dH[5] = F3 * zy * zy * zy + 3 * F2 * zy * zyy + F1 * zyyy;
}

static void sshock(double g[3], double *dg, double x, double y)
{
    double H[3], dH[6];
    sshock_hessian(H, dg ? dH : NULL, x, y);
    cvm__metric_hessian_abs(g, dg, H, dg ? dH : NULL, 0.005, 0.2, 50);
}

int cvm__metric_builtin_fn(void *payload, const double *x, int dim, double *g, double *dg)
{
    const cvm__metric_builtin *b = (const cvm__metric_builtin *)payload;
    double d[6] = {0, 0, 0, 0, 0, 0};
    int k;
    if (dim != 2)
        return 1;
    switch (b->kind) {
    case CVM__METRIC_CONSTANT:
        g[0] = b->g[0];
        g[1] = b->g[1];
        g[2] = b->g[2];
        break;
    case CVM__METRIC_IDENTITY:
        g[0] = g[2] = 1;
        g[1] = 0;
        break;
    case CVM__METRIC_STRETCH:
        g[0] = 1;
        g[1] = 0;
        g[2] = 1 + 4 * x[1] * x[1];
        d[5] = 8 * x[1];
        break;
    case CVM__METRIC_SADDLE: {
        double grad[2], H[3] = {2, 0, -2};
        grad[0] = 2 * x[0];
        grad[1] = -2 * x[1];
        cvm__metric_grad_outer(g, d, grad, H);
        break;
    }
    case CVM__METRIC_SSHOCK: /* without dg its third derivatives are not computed */
        sshock(g, dg ? d : NULL, x[0], x[1]);
        break;
    default:
        return 1;
    }
    for (k = 0; k < 3; k++)
        g[k] *= b->scale;
    if (dg)
        for (k = 0; k < 6; k++)
            dg[k] = b->scale * d[k];
    return 0;
}

/* Nearest point of the closed polygon bnd to y: *P, and the unit tangent *t of its edge when the
 * projection falls inside the edge (else t = 0: at a corner the point does not move with y). */
static void nearest_on_boundary(const cvm__metric *mt, const double y[2], double P[2], double t[2])
{
    double best = INFINITY;
    size_t k;
    for (k = 0; k < mt->nbnd; k++) {
        const double *a = mt->bnd + 2 * k, *b = mt->bnd + 2 * ((k + 1) % mt->nbnd);
        double ex = b[0] - a[0], ey = b[1] - a[1], l2 = ex * ex + ey * ey;
        double s = l2 > 0 ? ((y[0] - a[0]) * ex + (y[1] - a[1]) * ey) / l2 : 0, q[2], d2;
        int inside = s > 0 && s < 1;
        s = s < 0 ? 0 : s > 1 ? 1 : s;
        q[0] = a[0] + s * ex;
        q[1] = a[1] + s * ey;
        d2 = (y[0] - q[0]) * (y[0] - q[0]) + (y[1] - q[1]) * (y[1] - q[1]);
        if (d2 < best) {
            double l = sqrt(l2);
            best = d2;
            P[0] = q[0];
            P[1] = q[1];
            t[0] = inside ? ex / l : 0;
            t[1] = inside ? ey / l : 0;
        }
    }
}

/* The checks of every evaluation: g and its derivatives d finite, g positive definite. */
static cvm_status check_tensor(const double y[2], const double g[3], const double d[6],
                               cvm__ctx *err)
{
    int k;
    for (k = 0; k < 6; k++)
        if (!isfinite(d[k]) || (k < 3 && !isfinite(g[k])))
            return cvm__error(err, CVM_E_ARGUMENT, CVM_ENT_NONE, -1,
                              "the metric at (%.17g, %.17g) has a non-finite %s %d", y[0], y[1],
                              isfinite(g[k % 3]) ? "derivative" : "entry", k % 3);
    /* Sylvester's criterion; a measure check on plain doubles, not a topological decision */
    if (!(g[0] > 0) || !(g[0] * g[2] - g[1] * g[1] > 0))
        return cvm__error(err, CVM_E_ARGUMENT, CVM_ENT_NONE, -1,
                          "the metric at (%.17g, %.17g) is not positive definite: g11 = %.17g, "
                          "g12 = %.17g, g22 = %.17g", y[0], y[1], g[0], g[1], g[2]);
    return CVM_OK;
}

/* 1 when check_tensor() passes (no message): the quick test of the hot path. */
static int tensor_ok(const double g[3], const double d[6])
{
    int ok = g[0] > 0 && g[0] * g[2] - g[1] * g[1] > 0, k; /* false for NaN too */
    for (k = 0; k < 3; k++)
        ok &= isfinite(g[k]) != 0;
    for (k = 0; k < 6; k++)
        ok &= isfinite(d[k]) != 0;
    return ok;
}

cvm_status cvm__metric_eval(const cvm__metric *mt, const double y[2], double g[3], double *dg,
                            cvm__ctx *err)
{
    const cvm_sizing *s = mt->s;
    double d[6] = {0, 0, 0, 0, 0, 0}, P[2] = {0, 0}, t[2] = {0, 0};
    int k;
    cvm_status st;
    if (!s || !s->metric)
        return cvm__error(err, CVM_E_ARGUMENT, CVM_ENT_NONE, -1,
                          "the sizing has no metric: set one with cvm_sizing_set_metric_fn()");
    if (!s->metric_has_dg)
        return cvm__error(err, CVM_E_ARGUMENT, CVM_ENT_NONE, -1,
                          "the metric callback gives no derivatives: the Lp-CVT gradient needs "
                          "them (cvm_sizing_set_metric_fn() with has_derivatives = 1)");
    /* dg NULL: the callback may skip its derivatives (d stays 0 for the checks) */
    if (s->metric(s->metric_payload, y, 2, g, dg ? d : NULL) != 0) {
        if (!mt->bnd || mt->nbnd < 2)
            return cvm__error(err, CVM_E_ARGUMENT, CVM_ENT_NONE, -1,
                              "the metric callback refused the point (%.17g, %.17g)", y[0], y[1]);
        nearest_on_boundary(mt, y, P, t);
        if (s->metric(s->metric_payload, P, 2, g, dg ? d : NULL) != 0)
            return cvm__error(err, CVM_E_ARGUMENT, CVM_ENT_NONE, -1,
                              "the metric callback refused the point (%.17g, %.17g) and its "
                              "nearest boundary point (%.17g, %.17g)", y[0], y[1], P[0], P[1]);
        for (k = 0; k < 3; k++) { /* chain rule through the projection P(y): dP/dy = t t^T */
            double along = d[k] * t[0] + d[3 + k] * t[1];
            d[k] = along * t[0];
            d[3 + k] = along * t[1];
        }
    }
    if ((st = check_tensor(y, g, d, err)))
        return st;
    if (dg)
        for (k = 0; k < 6; k++)
            dg[k] = d[k];
    return CVM_OK;
}

cvm_status cvm__metric_eval_M(const cvm__metric *mt, const double y[2], double M[4], double *dM,
                              cvm__ctx *err)
{
    double g[3], dg[6];
    cvm_status st = cvm__metric_eval(mt, y, g, dg, err);
    if (st)
        return st;
    cvm__metric_factor(M, dM, g, dg);
    return CVM_OK;
}

/* M = diag(sqrt mu) [q1 q2]^T, q1 = (cs, sn), q2 = (-sn, cs), and dM from dmu (dmu[2k + m] =
 * d mu_k / d x_m) and dth, as cvm__metric_factor() writes them. */
static void factor_from_eig(double M[4], double dM[8], double cs, double sn, const double mu[2],
                            const double dmu[4], const double dth[2])
{
    double r0 = sqrt(mu[0]), r1 = sqrt(mu[1]), h0 = 0.5 / r0, h1 = 0.5 / r1;
    int k;
    M[0] = r0 * cs;
    M[1] = r0 * sn;
    M[2] = -r1 * sn;
    M[3] = r1 * cs;
    for (k = 0; k < 2; k++) {
        double a0 = dmu[k] * h0, a1 = dmu[2 + k] * h1, t = dth[k];
        dM[4 * k] = a0 * cs - r0 * sn * t;
        dM[4 * k + 1] = a0 * sn + r0 * cs * t;
        dM[4 * k + 2] = -a1 * sn - r1 * cs * t;
        dM[4 * k + 3] = a1 * cs - r1 * sn * t;
    }
}

/* A built-in field at y whose eigen-structure is known in closed form: M, dM straight from its
 * own eigen-directions, without decomposing g again. That M may differ from
 * cvm__metric_factor()'s by the sign or the order of its rows, which the energy (|M d|_p^p, p
 * even) does not see. Returns 1 (M, dM written, the checks pass), 2 (g and dg written: they
 * may fail check_tensor(), which says why), or 0 when the field is not one of these. */
static int builtin_M(const cvm__metric_builtin *b, const double *y, double g[3], double dg[6],
                     double M[4], double dM[8])
{
    double sc = b->scale, mu[2], dmu[4] = {0, 0, 0, 0}, dth[2] = {0, 0}, cs = 1, sn = 0;
    int k;
    switch (b->kind) {
    case CVM__METRIC_STRETCH: /* diag(1, 1 + 4 y^2): the axes */
        g[0] = sc;
        g[1] = 0;
        g[2] = sc * (1 + 4 * y[1] * y[1]);
        for (k = 0; k < 5; k++)
            dg[k] = 0;
        dg[5] = sc * 8 * y[1];
        mu[0] = g[0];
        mu[1] = g[2];
        dmu[3] = dg[5];
        break;
    case CVM__METRIC_SADDLE: { /* I + v v^T, v = grad f = (2x, -2y): 1 + |v|^2 along v, 1 across */
        double v0 = 2 * y[0], v1 = -2 * y[1], n2 = v0 * v0 + v1 * v1, grad[2], H[3] = {2, 0, -2};
        grad[0] = v0;
        grad[1] = v1;
        cvm__metric_grad_outer(g, dg, grad, H);
        for (k = 0; k < 3; k++) {
            g[k] *= sc;
            dg[k] *= sc;
            dg[3 + k] *= sc;
        }
        mu[0] = sc * (1 + n2);
        mu[1] = sc;
        dmu[0] = sc * 4 * v0; /* d|v|^2/dx = 2 v0 dv0/dx, dv0/dx = 2 */
        dmu[1] = -sc * 4 * v1;
        if (n2 > 0) { /* th = atan2(v1, v0); isotropic at v = 0, derivatives 0 there */
            double n = sqrt(n2);
            cs = v0 / n;
            sn = v1 / n;
            dth[0] = -2 * v1 / n2;
            dth[1] = -2 * v0 / n2;
        }
        break;
    }
    case CVM__METRIC_SSHOCK: {
        cvm__eig2 e;
        double H[3], dH[6];
        int ok;
        sshock_hessian(H, dH, y[0], y[1]);
        hessian_abs_eig(&e, mu, dmu, H, dH, 0.005, 0.2, 50);
        /* g itself only for a failing check's message: finite positive eigenvalues and finite
         * derivatives and directions make a finite SPD g with finite derivatives */
        ok = mu[0] > 0 && mu[1] > 0 && isfinite(sc * mu[0]) && isfinite(sc * mu[1]) &&
             isfinite(e.cs) && isfinite(e.sn) && isfinite(e.dth[0]) && isfinite(e.dth[1]);
        for (k = 0; k < 4; k++)
            ok = ok && isfinite(sc * dmu[k]);
        if (!ok) {
            cvm__eig2_compose(g, dg, e.cs, e.sn, mu, dmu, e.dth);
            for (k = 0; k < 3; k++) {
                g[k] *= sc;
                dg[k] *= sc;
                dg[3 + k] *= sc;
            }
            return 2;
        }
        for (k = 0; k < 4; k++)
            dmu[k] *= sc;
        mu[0] *= sc;
        mu[1] *= sc;
        if (mu[0] != mu[1]) { /* isotropic (both sizes clamped alike): the axes, as g's own */
            cs = e.cs;
            sn = e.sn;
            dth[0] = e.dth[0];
            dth[1] = e.dth[1];
        }
        break;
    }
    default:
        return 0;
    }
    factor_from_eig(M, dM, cs, sn, mu, dmu, dth);
    return b->kind == CVM__METRIC_SSHOCK || tensor_ok(g, dg) ? 1 : 2;
}

/* builtin_M() and factor_from_eig() of the stretch field over a batch, with the constant
 * eigenvalue's root and reciprocal taken once: the same bits. 0 when a point would fail the
 * checks (the caller's point-wise path then names it). */
static int stretch_M_batch(double sc, const double *y, size_t n, double *M, double *dM)
{
    const double cs = 1, sn = 0, t = 0;
    double r0 = sqrt(sc), h0 = 0.5 / r0;
    size_t q;
    if (!(sc > 0) || !isfinite(sc))
        return 0;
    for (q = 0; q < n; q++) {
        double g2 = sc * (1 + 4 * y[2 * q + 1] * y[2 * q + 1]), dg5 = sc * 8 * y[2 * q + 1];
        double r1, h1, a0, a1, *m = M + 4 * q, *d = dM + 8 * q;
        if (!(sc * g2 - 0.0 * 0.0 > 0) || !isfinite(g2) || !isfinite(dg5))
            return 0;
        r1 = sqrt(g2);
        h1 = 0.5 / r1;
        m[0] = r0 * cs;
        m[1] = r0 * sn;
        m[2] = -r1 * sn;
        m[3] = r1 * cs;
        a0 = 0 * h0; /* d mu0 = 0, d mu1 / dx = 0 */
        a1 = 0 * h1;
        d[0] = a0 * cs - r0 * sn * t;
        d[1] = a0 * sn + r0 * cs * t;
        d[2] = -a1 * sn - r1 * cs * t;
        d[3] = a1 * cs - r1 * sn * t;
        a1 = dg5 * h1; /* d mu1 / dy */
        d[4] = a0 * cs - r0 * sn * t;
        d[5] = a0 * sn + r0 * cs * t;
        d[6] = -a1 * sn - r1 * cs * t;
        d[7] = a1 * cs - r1 * sn * t;
    }
    return 1;
}

/* The S-shock field's M and dM at y straight from the Hessian's eigen-decomposition, with one
 * reciprocal per quantity: the roots r_k = sqrt(mu_k) of g's eigenvalues are sqrt|lam_k| of the
 * Hessian's, clamped to [1 / hmax, 1 / hmin] and to the aspect ratio, and
 * dr_k = sign(lam_k) dlam_k / (2 r_k) where not clamped. The same M and dM as builtin_M() up to
 * rounding. 0 when a value is not finite (the point-wise path then says which). */
static int sshock_M_fast(double rsc, const double *y, double *M, double *dM)
{
    const double hmin = 0.005, hmax = 0.2, aspect = 50;
    double H[3], dH[6], c, s, rho, m, ir = 0, ir2, cs, sn, lam[2], dlam[4], dth[2], r[2], dr[4];
    int k, j, big;
    sshock_hessian(H, dH, y[0], y[1]);
    c = H[0] - H[2];
    s = 2 * H[1];
    rho = sqrt(c * c + s * s);
    m = 0.5 * (H[0] + H[2]);
    ir = half_angle(c, s, rho, &cs, &sn);
    ir2 = ir * ir;
    lam[0] = m + 0.5 * rho;
    lam[1] = m - 0.5 * rho;
    for (k = 0; k < 2; k++) {
        double dc = dH[3 * k] - dH[3 * k + 2], ds = 2 * dH[3 * k + 1];
        double dm = 0.5 * (dH[3 * k] + dH[3 * k + 2]), drh = 0.5 * (c * dc + s * ds) * ir;
        dth[k] = 0.5 * (c * ds - s * dc) * ir2;
        dlam[k] = dm + drh;
        dlam[2 + k] = dm - drh;
    }
    for (k = 0; k < 2; k++) {
        double a = fabs(lam[k]), rk = sqrt(a);
        dr[2 * k] = dr[2 * k + 1] = 0;
        if (!(a > 0) || rk <= 1 / hmax) {
            r[k] = 1 / hmax;
        } else if (rk >= 1 / hmin) {
            r[k] = 1 / hmin;
        } else {
            double f = (lam[k] < 0 ? -0.5 : 0.5) / rk;
            r[k] = rk;
            for (j = 0; j < 2; j++)
                dr[2 * k + j] = f * dlam[2 * k + j];
        }
    }
    big = r[0] <= r[1] ? 0 : 1; /* the larger size: the smaller root */
    if (r[big] * aspect < r[1 - big]) {
        r[big] = r[1 - big] / aspect;
        for (j = 0; j < 2; j++)
            dr[2 * big + j] = dr[2 * (1 - big) + j] / aspect;
    }
    if (r[0] == r[1]) { /* isotropic: the axes */
        cs = 1;
        sn = 0;
        dth[0] = dth[1] = 0;
    }
    for (k = 0; k < 2; k++)
        r[k] *= rsc;
    for (k = 0; k < 4; k++)
        dr[k] *= rsc;
    M[0] = r[0] * cs;
    M[1] = r[0] * sn;
    M[2] = -r[1] * sn;
    M[3] = r[1] * cs;
    for (k = 0; k < 2; k++) {
        double a0 = dr[k], a1 = dr[2 + k], t = dth[k];
        dM[4 * k] = a0 * cs - r[0] * sn * t;
        dM[4 * k + 1] = a0 * sn + r[0] * cs * t;
        dM[4 * k + 2] = -a1 * sn - r[1] * cs * t;
        dM[4 * k + 3] = a1 * cs - r[1] * sn * t;
    }
    for (k = 0; k < 4; k++)
        if (!isfinite(M[k]) || !isfinite(dM[k]) || !isfinite(dM[4 + k]))
            return 0;
    return r[0] > 0 && r[1] > 0;
}

cvm_status cvm__metric_eval_M_batch(const cvm__metric *mt, const double *y, size_t n, double *M,
                                    double *dM, cvm__ctx *err)
{
    const cvm_sizing *s = mt->s;
    double g[3 * CVM__QUAD_MAXQ], dg[6 * CVM__QUAD_MAXQ];
    size_t q;
    cvm_status st;
    if (n > CVM__QUAD_MAXQ)
        return cvm__error(err, CVM_E_INTERNAL, CVM_ENT_NONE, -1,
                          "metric batch of %lu points (at most %d)", (unsigned long)n,
                          CVM__QUAD_MAXQ);
    if (s && s->metric == cvm__metric_builtin_fn && s->metric_has_dg) {
        /* the stretch and S-shock fields, each its own loop: a point that fails a check leaves
         * the batch to the point-wise path below, which names it */
        const cvm__metric_builtin *b = (const cvm__metric_builtin *)s->metric_payload;
        int done = 0;
        if (b->kind == CVM__METRIC_STRETCH) {
            done = stretch_M_batch(b->scale, y, n, M, dM);
        } else if (b->kind == CVM__METRIC_SSHOCK) {
            double rsc = sqrt(b->scale);
            for (q = 0; q < n && sshock_M_fast(rsc, y + 2 * q, M + 4 * q, dM + 8 * q); q++)
                ;
            done = q == n;
        }
        if (done)
            return CVM_OK;
    }
    for (q = 0; s && s->metric == cvm__metric_builtin_fn && s->metric_has_dg && q < n; q++) {
        int r = builtin_M((const cvm__metric_builtin *)s->metric_payload, y + 2 * q, g + 3 * q,
                          dg + 6 * q, M + 4 * q, dM + 8 * q);
        if (r == 0)
            break;
        if (r == 2 && (st = check_tensor(y + 2 * q, g + 3 * q, dg + 6 * q, err)))
            return st; /* the first point (in order) that fails the checks */
    }
    if (q == n && n > 0)
        return CVM_OK;
    for (q = 0; s && s->metric == cvm__metric_builtin_fn && s->metric_has_dg && q < n; q++)
        if (cvm__metric_builtin_fn(s->metric_payload, y + 2 * q, 2, g + 3 * q, dg + 6 * q) != 0)
            break; /* not a field of this version: the checked path says so */
    if (q == n) { /* a built-in field, called directly: it accepts every point */
        for (q = 0; q < n; q++)
            if ((st = check_tensor(y + 2 * q, g + 3 * q, dg + 6 * q, err)))
                return st;
    } else {
        for (q = 0; q < n; q++)
            if ((st = cvm__metric_eval(mt, y + 2 * q, g + 3 * q, dg + 6 * q, err)))
                return st;
    }
    for (q = 0; q < n; q++)
        factor_quick(M + 4 * q, dM + 8 * q, g + 3 * q, dg + 6 * q);
    return CVM_OK;
}
