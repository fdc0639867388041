/* boundary.c - the boundary of the quad mesher at unit metric length: adaptive Gauss-Kronrod
 * metric lengths and equal-length subdivision of each edge by Newton's method. */
#include <math.h>
#include <string.h>

#include "quad_internal.h"

/* Kronrod 15-point nodes on [-1, 1] (non-negative half, 0 last) and weights; the 7-point Gauss
 * rule uses the odd-numbered nodes (Piessens et al., QUADPACK, 1983). */
static const double xgk[8] = {0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
                              0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
                              0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
                              0.207784955007898467600689403773245, 0.0};
static const double wgk[8] = {0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
                              0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
                              0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
                              0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
static const double wg[4] = {0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
                             0.381830050505118944950369775488975, 0.417959183673469387755102040816327};

/* |b - a|_g at a + s (b - a). */
static cvm_status speed(double *out, const cvm__metric *mt, const double *a, const double *b,
                        double s, cvm__ctx *err)
{
    double e[2], y[2], g[3];
    cvm_status st;
    e[0] = b[0] - a[0];
    e[1] = b[1] - a[1];
    y[0] = a[0] + s * e[0];
    y[1] = a[1] + s * e[1];
    if ((st = cvm__metric_eval(mt, y, g, NULL, err)))
        return st;
    *out = sqrt(e[0] * e[0] * g[0] + 2 * e[0] * e[1] * g[1] + e[1] * e[1] * g[2]);
    return CVM_OK;
}

/* G7 and K15 on [s0, s1]. */
static cvm_status gk15(double *k15, double *g7, const cvm__metric *mt, const double *a,
                       const double *b, double s0, double s1, cvm__ctx *err)
{
    double c = 0.5 * (s0 + s1), h = 0.5 * (s1 - s0), fc, k = 0, g = 0;
    int j;
    cvm_status st;
    if ((st = speed(&fc, mt, a, b, c, err)))
        return st;
    k = wgk[7] * fc;
    g = wg[3] * fc;
    for (j = 0; j < 7; j++) {
        double f1, f2;
        if ((st = speed(&f1, mt, a, b, c - h * xgk[j], err)) ||
            (st = speed(&f2, mt, a, b, c + h * xgk[j], err)))
            return st;
        k += wgk[j] * (f1 + f2);
        if (j % 2)
            g += wg[j / 2] * (f1 + f2);
    }
    *k15 = k * h;
    *g7 = g * h;
    return CVM_OK;
}

/* Adaptive bisection until |K15 - G7| <= tol on each piece (depth at most 40). */
static cvm_status adapt(double *out, const cvm__metric *mt, const double *a, const double *b,
                        double s0, double s1, double tol, int depth, cvm__ctx *err)
{
    double k, g, l, r;
    cvm_status st;
    if ((st = gk15(&k, &g, mt, a, b, s0, s1, err)))
        return st;
    if (fabs(k - g) <= tol || depth >= 40) {
        *out = k;
        return CVM_OK;
    }
    if ((st = adapt(&l, mt, a, b, s0, 0.5 * (s0 + s1), 0.5 * tol, depth + 1, err)) ||
        (st = adapt(&r, mt, a, b, 0.5 * (s0 + s1), s1, 0.5 * tol, depth + 1, err)))
        return st;
    *out = l + r;
    return CVM_OK;
}

cvm_status cvm__metric_length(double *out, const cvm__metric *mt, const double *a, const double *b,
                              double s0, double s1, cvm__ctx *err)
{
    double k, g;
    cvm_status st;
    if ((st = gk15(&k, &g, mt, a, b, s0, s1, err)))
        return st;
    /* the tolerance is relative to a first estimate of the whole length */
    return adapt(out, mt, a, b, s0, s1, 1e-12 * fabs(k), 0, err);
}

/* The parameter s in (lo, 1) where the metric length from lo reaches want: Newton on
 * F(s) = length(lo, s) - want, F' = speed, kept inside the bracket by bisection. */
static cvm_status solve_length(double *s_out, const cvm__metric *mt, const double *a,
                               const double *b, double lo, double want, double guess, double total,
                               cvm__ctx *err)
{
    double s = guess, blo = lo, bhi = 1;
    int it;
    cvm_status st;
    for (it = 0; it < 100; it++) {
        double F, dF;
        if ((st = cvm__metric_length(&F, mt, a, b, lo, s, err)) || (st = speed(&dF, mt, a, b, s, err)))
            return st;
        F -= want;
        if (fabs(F) <= 1e-13 * total)
            break;
        if (F > 0)
            bhi = s;
        else
            blo = s;
        s -= F / dF;
        if (!(s > blo && s < bhi))
            s = 0.5 * (blo + bhi);
    }
    *s_out = s;
    return CVM_OK;
}

cvm_status cvm__boundary_discretise(double **xy_out, size_t *n_out, const cvm__metric *mt,
                                    const double *corners, size_t nc, cvm__ctx *ctx)
{
    double *xy = NULL, *len;
    size_t *pieces, k, total = 0, at = 0;
    cvm_status st = CVM_OK;
    *xy_out = NULL;
    *n_out = 0;
    len = cvm__malloc(ctx, nc * sizeof *len);
    pieces = cvm__malloc(ctx, nc * sizeof *pieces);
    if (!len || !pieces) {
        st = cvm__nomem(ctx);
        goto done;
    }
    for (k = 0; k < nc && !st; k++) {
        const double *a = corners + 2 * k, *b = corners + 2 * ((k + 1) % nc);
        st = cvm__metric_length(len + k, mt, a, b, 0, 1, ctx);
        if (!st && len[k] > 1073741824.0)
            st = cvm__error(ctx, CVM_E_TOO_LARGE, CVM_ENT_NONE, -1,
                            "boundary edge %lu has metric length %.6g: too many boundary sites",
                            (unsigned long)k, len[k]);
        pieces[k] = len[k] < 1.5 ? 1 : (size_t)floor(len[k] + 0.5);
        total += pieces[k];
    }
    if (st)
        goto done;
    if (total > ((size_t)1 << 30)) {
        st = cvm__error(ctx, CVM_E_TOO_LARGE, CVM_ENT_NONE, -1, "the boundary needs %lu sites",
                        (unsigned long)total);
        goto done;
    }
    xy = cvm__malloc(ctx, 2 * total * sizeof *xy);
    if (!xy) {
        st = cvm__nomem(ctx);
        goto done;
    }
    for (k = 0; k < nc && !st; k++) {
        const double *a = corners + 2 * k, *b = corners + 2 * ((k + 1) % nc);
        double s = 0;
        size_t j;
        xy[2 * at] = a[0];
        xy[2 * at + 1] = a[1];
        at++;
        for (j = 1; j < pieces[k] && !st; j++) {
            st = solve_length(&s, mt, a, b, s, len[k] / (double)pieces[k],
                              s + (1 - s) / (double)(pieces[k] - j + 1), len[k], ctx);
            xy[2 * at] = a[0] + s * (b[0] - a[0]);
            xy[2 * at + 1] = a[1] + s * (b[1] - a[1]);
            at++;
        }
    }
    if (st) {
        cvm__free(ctx, xy);
        xy = NULL;
    } else {
        *xy_out = xy;
        *n_out = total;
    }
done:
    cvm__free(ctx, len);
    cvm__free(ctx, pieces);
    return st;
}
