/* lpcvt_energy.c - the Lp-CVT energy and its exact gradient (the generic source instantiated for
 * double), and the same energy in complex arithmetic for complex-step checks. */
#include <string.h>

#include "quad_internal.h"

/* ---- the double instance, with the gradient ---- */
#define CVM__R double
#define CVM__G(name) lpcvt_d_##name
#define CVM__RE(z) (z)
#define CVM__IM(z) 0.0
#define CVM__MK(re, im) (re)
#define CVM__GRAD 1
#include "lpcvt_generic.h"
#undef CVM__R
#undef CVM__G
#undef CVM__RE
#undef CVM__IM
#undef CVM__MK
#undef CVM__GRAD

/* ---- the complex instance (C99 complex types; <complex.h> is not included because its macro I
 * would reach the rest of the amalgamation) ---- */
typedef double _Complex cvm__cplx;

static double cplx_re(cvm__cplx z)
{
    double d[2];
    memcpy(d, &z, sizeof d);
    return d[0];
}

static double cplx_im(cvm__cplx z)
{
    double d[2];
    memcpy(d, &z, sizeof d);
    return d[1];
}

static cvm__cplx cplx_make(double re, double im)
{
    double d[2];
    cvm__cplx z;
    d[0] = re;
    d[1] = im;
    memcpy(&z, d, sizeof z);
    return z;
}

#define CVM__R cvm__cplx
#define CVM__G(name) lpcvt_z_##name
#define CVM__RE(z) cplx_re(z)
#define CVM__IM(z) cplx_im(z)
#define CVM__MK(re, im) cplx_make(re, im)
#define CVM__GRAD 0
#include "lpcvt_generic.h"
#undef CVM__R
#undef CVM__G
#undef CVM__RE
#undef CVM__IM
#undef CVM__MK
#undef CVM__GRAD

/* Add J^T g to the sites of slot t, J the Jacobian of its circumcentre with respect to each
 * vertex (only the derivatives with respect to v and w are formed: the three sum to I). */
static void circumcentre_pullback(cvm__lpcvt *L, int32_t t, const double *g)
{
    const int32_t *tv = L->T.tv + 3 * (size_t)t;
    const double *u = L->xy + 2 * tv[0], *v = L->xy + 2 * tv[1], *w = L->xy + 2 * tv[2];
    double ax = v[0] - u[0], ay = v[1] - u[1], bx = w[0] - u[0], by = w[1] - u[1];
    double d = 2 * (ax * by - ay * bx), a2 = ax * ax + ay * ay, b2 = bx * bx + by * by;
    double rx = (by * a2 - ay * b2) / d, ry = (ax * b2 - bx * a2) / d;
    double Jv[4], Jw[4], gv[2], gw[2]; /* J[2 row + col] = d c_row / d (vertex)_col */
    Jv[0] = (2 * ax * by - rx * 2 * by) / d;
    Jv[2] = (b2 - 2 * ax * bx - ry * 2 * by) / d;
    Jv[1] = (2 * ay * by - b2 + rx * 2 * bx) / d;
    Jv[3] = (-2 * ay * bx + ry * 2 * bx) / d;
    Jw[0] = (-2 * ay * bx + rx * 2 * ay) / d;
    Jw[2] = (2 * ax * bx - a2 + ry * 2 * ay) / d;
    Jw[1] = (a2 - 2 * ay * by - rx * 2 * ax) / d;
    Jw[3] = (2 * ax * by - ry * 2 * ax) / d;
    gv[0] = Jv[0] * g[0] + Jv[2] * g[1];
    gv[1] = Jv[1] * g[0] + Jv[3] * g[1];
    gw[0] = Jw[0] * g[0] + Jw[2] * g[1];
    gw[1] = Jw[1] * g[0] + Jw[3] * g[1];
    L->gsite[2 * tv[1]] += gv[0];
    L->gsite[2 * tv[1] + 1] += gv[1];
    L->gsite[2 * tv[2]] += gw[0];
    L->gsite[2 * tv[2] + 1] += gw[1];
    L->gsite[2 * tv[0]] += g[0] - gv[0] - gw[0];
    L->gsite[2 * tv[0] + 1] += g[1] - gv[1] - gw[1];
}

/* dE/d polygon vertex (L->gpv) back to the sites: circumcentres to their triangle, triangles
 * to their vertices. */
static void pullback(cvm__lpcvt *L)
{
    size_t k, t;
    for (t = 0; t < 2 * L->T.nt; t++)
        L->gcc[t] = 0;
    for (k = 0; k < L->npv; k++) {
        const cvm__pvert *v = L->pv + k;
        if (v->kind == CVM__PV_CC) {
            L->gcc[2 * v->t] += L->gpv[2 * k];
            L->gcc[2 * v->t + 1] += L->gpv[2 * k + 1];
        }
    }
    for (t = 0; t < L->T.nt; t++)
        if (cvm__tri2_in_domain(&L->T, (int32_t)t) && (L->gcc[2 * t] != 0 || L->gcc[2 * t + 1] != 0))
            circumcentre_pullback(L, (int32_t)t, L->gcc + 2 * t);
}

cvm_status cvm__lpcvt_eval(cvm__lpcvt *L, const double *xi, double *E, double *grad)
{
    double *pos;
    cvm_status st;
    size_t k;
    if ((st = cvm__lpcvt_topology(L, xi)) || !L->valid)
        return st;
    pos = cvm__malloc(L->ctx, 2 * L->npv * sizeof *pos);
    if (!pos)
        return cvm__nomem(L->ctx);
    st = lpcvt_d_energy(E, L, L->xy, L->cc, pos);
    cvm__free(L->ctx, pos);
    if (st || !grad)
        return st;
    pullback(L);
    for (k = 0; k < 2 * (L->ns - L->nb); k++)
        grad[k] = L->gsite[2 * L->nb + k];
    return CVM_OK;
}

cvm_status cvm__lpcvt_energy_complex(cvm__lpcvt *L, const double *xyz, double E_out[2])
{
    cvm__cplx *xy, *cc, *pos, E = 0;
    size_t k;
    cvm_status st;
    xy = cvm__malloc(L->ctx, 2 * L->nall * sizeof *xy);
    cc = cvm__malloc(L->ctx, (2 * L->T.nt + 1) * sizeof *cc);
    pos = cvm__malloc(L->ctx, (2 * L->npv + 1) * sizeof *pos);
    if (!xy || !cc || !pos) {
        st = cvm__nomem(L->ctx);
    } else {
        for (k = 0; k < 2 * L->nall; k++)
            xy[k] = cplx_make(xyz[2 * k], xyz[2 * k + 1]);
        st = lpcvt_z_energy(&E, L, xy, cc, pos);
    }
    cvm__free(L->ctx, xy);
    cvm__free(L->ctx, cc);
    cvm__free(L->ctx, pos);
    E_out[0] = cplx_re(E);
    E_out[1] = cplx_im(E);
    return st;
}
