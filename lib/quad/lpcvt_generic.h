/* lpcvt_generic.h - the Lp-CVT energy written once for any arithmetic type: lpcvt_energy.c
 * includes it for double (with the gradient) and for double _Complex (complex-step checks).
 * Deliberately without an include guard; the includer defines:
 *   CVM__R           the number type
 *   CVM__G(name)     the instance's name for name
 *   CVM__RE(z), CVM__IM(z)  real and imaginary parts (a double)
 *   CVM__MK(re, im)  the number re + i im (re when CVM__R is real)
 *   CVM__GRAD        1: also accumulate dE/d site into L->gsite and dE/d polygon vertex into L->gpv
 * The metric is evaluated at the real part of a point y (each quadrature point, or the site when
 * L->cellwise) and extended to first order, M(y) = M(Re y) + i dM(Re y) Im y, which is all a
 * complex step reads. */

static void CVM__G(circumcentre)(CVM__R *c, const CVM__R *u, const CVM__R *v, const CVM__R *w)
{
    CVM__R ax = v[0] - u[0], ay = v[1] - u[1], bx = w[0] - u[0], by = w[1] - u[1];
    CVM__R d = 2 * (ax * by - ay * bx), a2 = ax * ax + ay * ay, b2 = bx * bx + by * by;
    c[0] = u[0] + (by * a2 - ay * b2) / d;
    c[1] = u[1] + (ax * b2 - bx * a2) / d;
}

static CVM__R CVM__G(ipow)(CVM__R u, int p)
{
    CVM__R r = u;
    int k;
    for (k = 1; k < p; k++)
        r *= u;
    return r;
}

/* The positions of the polygon vertices of every cell from the circumcentres cc. */
static void CVM__G(positions)(CVM__R *pos, const CVM__R *cc, const cvm__lpcvt *L)
{
    size_t k;
    for (k = 0; k < L->npv; k++) {
        const cvm__pvert *v = L->pv + k;
        if (v->kind == CVM__PV_FIXED) {
            pos[2 * k] = v->off[0];
            pos[2 * k + 1] = v->off[1];
        } else {
            pos[2 * k] = cc[2 * v->t];
            pos[2 * k + 1] = cc[2 * v->t + 1];
        }
    }
}

/* sum_{i=0..p} u^i v^(p-i) (the integral of a linear form to the power p over a triangle, up to
 * 2 area / ((p+1)(p+2)), from its values 0, u, v at the corners: int lam1^i lam2^j = 2 |T| i! j! /
 * (i+j+2)!); with CVM__GRAD also its derivatives in u and v. */
static CVM__R CVM__G(hsum)(CVM__R u, CVM__R v, int p
#if CVM__GRAD
                           , double *du, double *dv
#endif
)
{
    CVM__R U[13], V[13], h = 0;
    int i;
    U[0] = V[0] = 1;
    for (i = 1; i <= p; i++) {
        U[i] = U[i - 1] * u;
        V[i] = V[i - 1] * v;
    }
    for (i = 0; i <= p; i++)
        h += U[i] * V[p - i];
#if CVM__GRAD
    *du = *dv = 0;
    for (i = 1; i <= p; i++) {
        *du += i * U[i - 1] * V[p - i];
        *dv += i * V[i - 1] * U[p - i];
    }
#endif
    return h;
}

/* The fan triangle (x, a, b) under one matrix Me (the metric constant over it): E in closed
 * form, exact for every p (the quadrature's degree-p rule gives the same value up to rounding);
 * with CVM__GRAD its derivatives, the metric-derivative term through dM at x (cellwise). */
static cvm_status CVM__G(fan_exact)(CVM__R *e, const cvm__lpcvt *L, const CVM__R *x,
                                    const CVM__R *a, const CVM__R *b, CVM__R area,
                                    const CVM__R *Me
#if CVM__GRAD
                                    , const double *M, const double *dM, double *gx, double *ga,
                                    double *gb
#endif
)
{
    CVM__R e1[2], e2[2], S = 0;
    double c = 2.0 / ((L->p + 1) * (L->p + 2));
    int k;
#if CVM__GRAD
    double hA[2], hB[2], dS1[2], dS2[2], dAa[2], dAb[2];
    int m;
#endif
    e1[0] = a[0] - x[0];
    e1[1] = a[1] - x[1];
    e2[0] = b[0] - x[0];
    e2[1] = b[1] - x[1];
    for (k = 0; k < 2; k++) {
        CVM__R al = Me[2 * k] * e1[0] + Me[2 * k + 1] * e1[1];
        CVM__R be = Me[2 * k] * e2[0] + Me[2 * k + 1] * e2[1];
        S += CVM__G(hsum)(al, be, L->p
#if CVM__GRAD
                          , hA + k, hB + k
#endif
        );
    }
    *e = c * area * S;
#if CVM__GRAD
    dAa[0] = 0.5 * e2[1];
    dAa[1] = -0.5 * e2[0];
    dAb[0] = -0.5 * e1[1];
    dAb[1] = 0.5 * e1[0];
    for (m = 0; m < 2; m++) {
        double dMx = 0;
        dS1[m] = hA[0] * M[m] + hA[1] * M[2 + m];
        dS2[m] = hB[0] * M[m] + hB[1] * M[2 + m];
        if (!L->mconst) /* M = M(x): its derivative along x_m */
            for (k = 0; k < 2; k++)
                dMx += hA[k] * (dM[4 * m + 2 * k] * e1[0] + dM[4 * m + 2 * k + 1] * e1[1]) +
                       hB[k] * (dM[4 * m + 2 * k] * e2[0] + dM[4 * m + 2 * k + 1] * e2[1]);
        ga[m] += c * (dAa[m] * S + area * dS1[m]);
        gb[m] += c * (dAb[m] * S + area * dS2[m]);
        gx[m] += c * (area * (dMx - dS1[m] - dS2[m]) - (dAa[m] + dAb[m]) * S);
    }
#endif
    return CVM_OK;
}

/* E of the fan triangle (x, a, b) into *e; with CVM__GRAD also its derivatives added to gx, ga, gb. */
static cvm_status CVM__G(fan)(CVM__R *e, cvm__lpcvt *L, cvm__ctx *err, const CVM__R *x,
                              const CVM__R *a, const CVM__R *b
#if CVM__GRAD
                              , double *gx, double *ga, double *gb
#endif
)
{
    CVM__R area = 0.5 * ((a[0] - x[0]) * (b[1] - x[1]) - (a[1] - x[1]) * (b[0] - x[0])), sum = 0;
    CVM__R Me[4] = {0, 0, 0, 0};
    double M[4] = {0, 0, 0, 0}, dM[8] = {0, 0, 0, 0, 0, 0, 0, 0};
    double Mb[4 * CVM__QUAD_MAXQ], dMb[8 * CVM__QUAD_MAXQ];
    size_t q;
    int p = L->p, k;
#if CVM__GRAD
    double fy[2] = {0, 0}, fyl0[2] = {0, 0}, fyl1[2] = {0, 0}, fx[2] = {0, 0};
#endif
    if (L->mconst) { /* the same M everywhere: the energy of every sampling */
        for (k = 0; k < 4; k++) {
            M[k] = L->Mc[k];
            Me[k] = CVM__MK(M[k], 0.0);
        }
    } else if (L->cellwise) { /* M(x_i) for the whole cell */
        double xr[2];
        cvm_status st;
        xr[0] = CVM__RE(x[0]);
        xr[1] = CVM__RE(x[1]);
        if ((st = cvm__metric_eval_M(&L->metric, xr, M, dM, err)))
            return st;
        for (k = 0; k < 4; k++)
            Me[k] = CVM__MK(M[k], CVM__IM(x[0]) * dM[k] + CVM__IM(x[1]) * dM[4 + k]);
    }
    if (L->mconst || L->cellwise)
        return CVM__G(fan_exact)(e, L, x, a, b, area, Me
#if CVM__GRAD
                                 , M, dM, gx, ga, gb
#endif
        );
    { /* the metric at every quadrature point first: one batch, independent evaluations */
        double yr[2 * CVM__QUAD_MAXQ];
        cvm_status st;
        for (q = 0; q < L->nq; q++) {
            const double *r = L->rule[q];
            yr[2 * q] = CVM__RE(r[0] * x[0] + r[1] * a[0] + r[2] * b[0]);
            yr[2 * q + 1] = CVM__RE(r[0] * x[1] + r[1] * a[1] + r[2] * b[1]);
        }
        if ((st = cvm__metric_eval_M_batch(&L->metric, yr, L->nq, Mb, dMb, err)))
            return st;
    }
    for (q = 0; q < L->nq; q++) {
        const double *r = L->rule[q], *Mp = Mb + 4 * q, *dMp = dMb + 8 * q;
        CVM__R y[2], d[2], u0, u1;
        y[0] = r[0] * x[0] + r[1] * a[0] + r[2] * b[0];
        y[1] = r[0] * x[1] + r[1] * a[1] + r[2] * b[1];
        for (k = 0; k < 4; k++) /* M(y) and, for a complex step, its first-order extension */
            Me[k] = CVM__MK(Mp[k], CVM__IM(y[0]) * dMp[k] + CVM__IM(y[1]) * dMp[4 + k]);
        d[0] = y[0] - x[0];
        d[1] = y[1] - x[1];
        u0 = Me[0] * d[0] + Me[1] * d[1];
        u1 = Me[2] * d[0] + Me[3] * d[1];
#if CVM__GRAD
        {
            /* u^p as u^(p-1) u: the same products in the same order as ipow(u, p) */
            double v0, v1, r0, r1;
            int m;
            if (p == 6) { /* the default, unrolled: the same left-to-right products */
                v0 = u0 * u0 * u0 * u0 * u0;
                v1 = u1 * u1 * u1 * u1 * u1;
            } else {
                v0 = CVM__G(ipow)(u0, p - 1);
                v1 = CVM__G(ipow)(u1, p - 1);
            }
            r0 = r[3] * p * v0;
            r1 = r[3] * p * v1;
            sum += r[3] * (v0 * u0 + v1 * u1);
            for (m = 0; m < 2; m++) {
                /* d f / d y_m = sum_k r_k (M_km + sum_l dM_kl/dy_m d_l) with M at y, and the direct
                 * term -r^T M (plus that dM term when M is taken at the site) */
                double dMd = r0 * (dMp[4 * m] * d[0] + dMp[4 * m + 1] * d[1]) +
                             r1 * (dMp[4 * m + 2] * d[0] + dMp[4 * m + 3] * d[1]);
                double dy = r0 * Mp[m] + r1 * Mp[2 + m] + (L->cellwise ? 0 : dMd);
                fy[m] += r[0] * dy;
                fyl0[m] += r[1] * dy;
                fyl1[m] += r[2] * dy;
                fx[m] += (L->cellwise ? dMd : 0) - r0 * Mp[m] - r1 * Mp[2 + m];
            }
        }
#else
        sum += r[3] * (CVM__G(ipow)(u0, p) + CVM__G(ipow)(u1, p));
#endif
    }
    *e = area * sum;
#if CVM__GRAD
    {
        double dAa[2], dAb[2];
        dAa[0] = 0.5 * (b[1] - x[1]);
        dAa[1] = -0.5 * (b[0] - x[0]);
        dAb[0] = -0.5 * (a[1] - x[1]);
        dAb[1] = 0.5 * (a[0] - x[0]);
        gx[0] += area * (fy[0] + fx[0]) - (dAa[0] + dAb[0]) * sum;
        gx[1] += area * (fy[1] + fx[1]) - (dAa[1] + dAb[1]) * sum;
        ga[0] += area * fyl0[0] + dAa[0] * sum;
        ga[1] += area * fyl0[1] + dAa[1] * sum;
        gb[0] += area * fyl1[0] + dAb[0] * sum;
        gb[1] += area * fyl1[1] + dAb[1] * sum;
    }
#endif
    return CVM_OK;
}

/* The energy of cell i into *e_out (with CVM__GRAD also L->ecell[i], and its derivatives added to
 * L->gsite for site i and L->gpv for its polygon vertices: nothing another cell writes). */
static cvm_status CVM__G(cell)(CVM__R *e_out, cvm__lpcvt *L, size_t i, const CVM__R *xy,
                               const CVM__R *pos, cvm__ctx *err)
{
    size_t a = L->cstart[i], n = L->cstart[i + 1] - a, nf = L->copen[i] ? n - 1 : n, j;
    CVM__R E = 0;
    cvm_status st;
    for (j = 0; j < nf; j++) {
        size_t k0 = a + j, k1 = a + (j + 1) % n;
        CVM__R e;
        if ((st = CVM__G(fan)(&e, L, err, xy + 2 * i, pos + 2 * k0, pos + 2 * k1
#if CVM__GRAD
                              , L->gsite + 2 * i, L->gpv + 2 * k0, L->gpv + 2 * k1
#endif
                              )))
            return st;
        E += e;
    }
#if CVM__GRAD
    L->ecell[i] = E;
#endif
    *e_out = E;
    return CVM_OK;
}

/* E of the configuration xy (2 per site) on the topology of L; cc and pos are scratch of 2 per
 * triangle slot and 2 per polygon vertex. The cells are summed in their order whatever the
 * number of threads (L->threads, the double instance only), so E and the gradient are the same
 * bits for any count. */
static cvm_status CVM__G(energy)(CVM__R *E_out, cvm__lpcvt *L, const CVM__R *xy, CVM__R *cc,
                                 CVM__R *pos)
{
    const cvm__tri2 *T = &L->T;
    CVM__R E = 0, e;
    size_t t, i;
    cvm_status st;
    for (t = 0; t < T->nt; t++)
        if (cvm__tri2_in_domain(T, (int32_t)t)) {
            const int32_t *v = T->tv + 3 * t;
            CVM__G(circumcentre)(cc + 2 * t, xy + 2 * v[0], xy + 2 * v[1], xy + 2 * v[2]);
        }
    CVM__G(positions)(pos, cc, L);
#if CVM__GRAD
    for (i = 0; i < 2 * L->nall; i++)
        L->gsite[i] = 0;
    for (i = 0; i < 2 * L->npv; i++)
        L->gpv[i] = 0;
#if defined(_OPENMP)
    if (L->threads > 1 && L->ns > 256) {
        long il, nsl = (long)L->ns;
#pragma omp parallel for schedule(dynamic, 64) num_threads(L->threads)
        for (il = 0; il < nsl; il++) {
            cvm__ctx local = *L->ctx; /* a failing cell's message stays with its thread */
            CVM__R el;
            L->cstat[il] = CVM__G(cell)(&el, L, (size_t)il, xy, pos, &local) != CVM_OK;
        }
        for (i = 0; i < L->ns; i++) {
            if (L->cstat[i]) /* the first failing cell again, for its message on L->ctx */
                return CVM__G(cell)(&e, L, i, xy, pos, L->ctx);
            E += L->ecell[i];
        }
        *E_out = E;
        return CVM_OK;
    }
#endif
#endif
    for (i = 0; i < L->ns; i++) {
        if ((st = CVM__G(cell)(&e, L, i, xy, pos, L->ctx)))
            return st;
        E += e;
    }
    *E_out = E;
    return CVM_OK;
}
