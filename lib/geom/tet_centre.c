/*
 * tet_centre.c - on which side of each face of a tetrahedron its circumcentre
 * (power vertex, with weights) lies, decided exactly: a floating-point filter,
 * then expansion arithmetic on power-of-two rescaled coordinates.
 */
#include <math.h>
#include <string.h>

#include "geom/exact_det.h"
#include "geom/expansion.h"
#include "geom/geom_internal.h"

/*
 * Filter (translated so that d is the origin): u = a - d, v = b - d, t = c - d,
 * c1 = v x t, c2 = t x u, c3 = u x v, D = u . c1, r_p = |p - d|^2 - (w_p - w_d).
 * The power vertex is d + N / (2 D) with N = r_a c1 + r_b c2 + r_c c3, so its
 * barycentric coordinates are N.c1, N.c2, N.c3 and 2 D^2 - N.(c1 + c2 + c3),
 * each over 2 D^2 > 0: the signs of these four degree-6 polynomials.
 *
 * Error bound: counting the rounding of each difference, every monomial of the
 * longest of them carries at most 23 factors (1 + delta); gamma_32 times the
 * permanent (the same expression with absolute values) leaves room for the
 * rounding of the permanent itself. The floor sends results that may have
 * underflowed to the exact stage, and so does an overflow (inf or NaN fails
 * the comparison).
 */
static const double centre_errbound = (32.0 + 4096.0 * CVM__EPS) * CVM__EPS;

static void cross3(const double *p, const double *q, double *o, double *op)
{
    double a = p[1] * q[2], b = p[2] * q[1], c = p[2] * q[0], d = p[0] * q[2];
    double e = p[0] * q[1], f = p[1] * q[0];
    o[0] = a - b, o[1] = c - d, o[2] = e - f;
    op[0] = fabs(a) + fabs(b), op[1] = fabs(c) + fabs(d), op[2] = fabs(e) + fabs(f);
}

/* The four signs by the filter; 1 when all four are certain. */
static int centre_filter(const double *P[4], const double *w, int s[4])
{
    double u[3][3], c[3][3], cp[3][3], r[3], rp[3], n[3], np[3], dd = 0, dp = 0;
    double val[4], perm[4], cs, csp;
    int i, k;
    for (i = 0; i < 3; i++) {
        for (k = 0; k < 3; k++)
            u[i][k] = P[i][k] - P[3][k];
        r[i] = u[i][0] * u[i][0] + u[i][1] * u[i][1] + u[i][2] * u[i][2];
        rp[i] = r[i];
        if (w) {
            double dw = w[i] - w[3];
            r[i] -= dw;
            rp[i] += fabs(dw);
        }
    }
    cross3(u[1], u[2], c[0], cp[0]);
    cross3(u[2], u[0], c[1], cp[1]);
    cross3(u[0], u[1], c[2], cp[2]);
    for (k = 0; k < 3; k++) {
        n[k] = r[0] * c[0][k] + r[1] * c[1][k] + r[2] * c[2][k];
        np[k] = rp[0] * cp[0][k] + rp[1] * cp[1][k] + rp[2] * cp[2][k];
        dd += u[0][k] * c[0][k];
        dp += fabs(u[0][k]) * cp[0][k];
    }
    for (i = 0; i < 3; i++) {
        val[i] = n[0] * c[i][0] + n[1] * c[i][1] + n[2] * c[i][2];
        perm[i] = np[0] * cp[i][0] + np[1] * cp[i][1] + np[2] * cp[i][2];
    }
    val[3] = 2 * dd * dd;
    perm[3] = 2 * dp * dp;
    for (k = 0; k < 3; k++) {
        cs = c[0][k] + c[1][k] + c[2][k];
        csp = cp[0][k] + cp[1][k] + cp[2][k];
        val[3] -= n[k] * cs;
        perm[3] += np[k] * csp;
    }
    for (i = 0; i < 4; i++) {
        double bound = centre_errbound * perm[i] + cvm__filter_floor;
        if (!(fabs(val[i]) > bound))
            return 0;
        s[i] = val[i] > 0 ? 1 : -1;
    }
    return 1;
}

/*
 * Exact stage, on the raw coordinates. With A the 4x4 matrix of rows (p, 1)
 * for p = a, b, c, d and zeta_p = |p|^2 - w_p, the power vertex o solves
 * A (2 o, k) = zeta, so 2 o_j = Q_j / Delta with Delta = det A and Q_j = det A
 * with column j replaced by zeta (Cramer). The barycentric coordinate of o for
 * a is det[o 1; b 1; c 1; d 1] / Delta = F(b, c, d) / (2 Delta^2) with
 * F(p, q, r) = det[Q 2Delta; p 1; q 1; r 1], and likewise for b, c, d with the
 * row of R = (Q, 2 Delta) moved to the front (a sign per transposition).
 *
 * Lengths: a nonoverlapping expansion has at most one component per bit
 * position of a double (2098 of them), so EXP_MAX bounds every expansion here
 * whatever the worst-case sums of lengths say.
 */
#define EXP_MAX 2112

typedef struct centre_work {
    double q[3][672];
    int nq[3];
    double d2[96];
    int nd2;
    double term[EXP_MAX], acc[2][EXP_MAX], scaled[EXP_MAX], prod[2][EXP_MAX];
} centre_work;

/* h = e * f, h distinct from e, f and the buffers of wk used here. */
static int exp_product(centre_work *wk, int elen, const double *e, int flen, const double *f,
                       double *h)
{
    int i, n = 0, cur = 0, sn;
    if (elen < flen) { /* scale the longer one by the components of the shorter */
        const double *t = e;
        int tl = elen;
        e = f, elen = flen, f = t, flen = tl;
    }
    for (i = 0; i < flen; i++) {
        sn = cvm__scale_expansion_zeroelim(elen, e, f[i], wk->scaled);
        if (i == 0) {
            memcpy(wk->prod[0], wk->scaled, (size_t)sn * sizeof(double));
            n = sn;
        } else {
            n = cvm__fast_expansion_sum_zeroelim(n, wk->prod[cur], sn, wk->scaled,
                                                 wk->prod[1 - cur]);
            cur = 1 - cur;
        }
    }
    memcpy(h, wk->prod[cur], (size_t)n * sizeof(double));
    return n;
}

/* The (k, l) projection of p, for cvm__orient2d_raw. */
static void proj(const double *p, int k, int l, double *o)
{
    o[0] = p[k];
    o[1] = p[l];
}

/* Sign of F(p[0], p[1], p[2]) = det[R; p 1], R = (Q_0, Q_1, Q_2, 2 Delta) in wk. */
static int centre_f(centre_work *wk, const double *p[3])
{
    static const int cols[3][2] = {{1, 2}, {0, 2}, {0, 1}};
    double pp[3][2], m[96];
    int j, mn, tn, n = 0, cur = 0, i;
    for (j = 0; j < 4; j++) {
        if (j < 3) {
            for (i = 0; i < 3; i++)
                proj(p[i], cols[j][0], cols[j][1], pp[i]);
            mn = cvm__orient2d_raw(pp[0], pp[1], pp[2], m);
            if (j % 2)
                for (i = 0; i < mn; i++)
                    m[i] = -m[i];
            tn = exp_product(wk, wk->nq[j], wk->q[j], mn, m, wk->term);
        } else {
            static const double zero[3] = {0, 0, 0};
            mn = cvm__orient3d_raw(p[0], p[1], p[2], zero, m); /* det[p; q; r] */
            for (i = 0; i < mn; i++)
                m[i] = -m[i];
            tn = exp_product(wk, wk->nd2, wk->d2, mn, m, wk->term);
        }
        if (j == 0) {
            memcpy(wk->acc[0], wk->term, (size_t)tn * sizeof(double));
            n = tn;
        } else {
            n = cvm__fast_expansion_sum_zeroelim(n, wk->acc[cur], tn, wk->term,
                                                 wk->acc[1 - cur]);
            cur = 1 - cur;
        }
    }
    return (wk->acc[cur][n - 1] > 0) - (wk->acc[cur][n - 1] < 0);
}

/* About 120 KB of stack, only on this path. */
static CVM__NOINLINE void centre_exact(const double *P[4], const double *w, int s[4])
{
    static const int cols[3][2] = {{1, 2}, {0, 2}, {0, 1}};
    centre_work wks, *wk = &wks;
    double pp[3][2], t[12], term[168], sum[2][672];
    int i, j, r, k, tn, n = 0, cur = 0;
    for (j = 0; j < 3; j++) {
        /* Q_j along the zeta column: sum_i zeta_i (-1)^(i+j) minor_ij, the minor
         * the orient2d of the other three points projected on the other two axes */
        for (i = 0; i < 4; i++) {
            for (k = 0, r = 0; k < 4; k++)
                if (k != i)
                    proj(P[k], cols[j][0], cols[j][1], pp[r++]);
            tn = cvm__orient2d_raw(pp[0], pp[1], pp[2], t);
            tn = cvm__lift_scale(tn, t, P[i], 3, w ? w[i] : 0.0, ((i + j) % 2) ? -1.0 : 1.0,
                                 term);
            if (i == 0) {
                memcpy(sum[0], term, (size_t)tn * sizeof(double));
                n = tn;
            } else {
                n = cvm__fast_expansion_sum_zeroelim(n, sum[cur], tn, term, sum[1 - cur]);
                cur = 1 - cur;
            }
        }
        memcpy(wk->q[j], sum[cur], (size_t)n * sizeof(double));
        wk->nq[j] = n;
        cur = 0;
    }
    wk->nd2 = cvm__orient3d_raw(P[0], P[1], P[2], P[3], wk->d2);
    for (i = 0; i < wk->nd2; i++)
        wk->d2[i] *= 2.0;
    for (i = 0; i < 4; i++) {
        const double *rest[3];
        for (k = 0, r = 0; k < 4; k++)
            if (k != i)
                rest[r++] = P[k];
        /* row i moved to the front past i rows */
        s[i] = (i % 2 ? -1 : 1) * centre_f(wk, rest);
    }
}

int cvm__tet_centre_side(const double *a, const double *b, const double *c, const double *d,
                         const double *w, int s[4])
{
    const double *P[4];
    double sc[4][3], sw[4], m = 0.0, mw = 0.0;
    int i, j, k;
    P[0] = a, P[1] = b, P[2] = c, P[3] = d;
    if (cvm__orient3d(a, b, c, d) == 0.0)
        return -1;
    if (centre_filter(P, w, s))
        return 0;
    for (i = 0; i < 4; i++) {
        if (w)
            mw = cvm__maxabs(mw, w[i]);
        for (j = 0; j < 3; j++)
            m = cvm__maxabs(m, P[i][j]);
    }
    k = cvm__rescale_exponent(cvm__maxabs(m, sqrt(mw)));
    if (k != 0) { /* degree 6 in the coordinates (a weight counts 2): the signs stay */
        for (i = 0; i < 4; i++) {
            for (j = 0; j < 3; j++)
                sc[i][j] = ldexp(P[i][j], k);
            sw[i] = w ? ldexp(w[i], 2 * k) : 0.0;
            P[i] = sc[i];
        }
        w = sw;
    }
    centre_exact(P, w, s);
    return 0;
}

int cvm__tet_centre_inside(const double *a, const double *b, const double *c, const double *d,
                           const double *w)
{
    int s[4], i, on = 0;
    if (cvm__tet_centre_side(a, b, c, d, w, s))
        return -2;
    for (i = 0; i < 4; i++) {
        if (s[i] < 0)
            return -1;
        on += s[i] == 0;
    }
    return on ? 0 : 1;
}
