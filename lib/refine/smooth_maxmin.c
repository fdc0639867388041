/* smooth_maxmin.c - post-processing by Freitag-Ollivier max-min optimisation of the sines of the angles of a vertex's star (active-set method), with the star evaluation of smooth_star.c. */
#include <limits.h>
#include <math.h>
#include <string.h>

#include "smooth.h"
#include "delaunay/tri2_store.h"
#include "geom/geom_internal.h"

/* Largest number of active-set iterations per vertex visit, and of step
 * halvings in each line search. */
#define MM_ITERS 12
#define MM_HALVINGS 10
/* functions within this of the minimum are active (Freitag's tolerance) */
#define MM_ACTIVE_TOL 1e-6

/* Sine of every angle of the star of v with v at p: f[3k..3k+2] for star
 * triangle k (angles at v, a, b) and their gradients with respect to p in
 * g (2 per function, when g is not NULL); *fmin = the smallest, *big = star
 * triangles above the size bound (as cvm__sm_ring_eval). Returns 0 when a
 * triangle is not strictly counter-clockwise (exact orient2d). */
static int mm_eval(const cvm__refiner *R, int32_t v, const double *p, const int32_t *star,
                   size_t n, double *f, double *g, double *fmin, int *big)
{
    const cvm__tri2 *T = R->T;
    size_t k;
    double m = 2.0;
    int sbig = 0;
    for (k = 0; k < n; k++) {
        const int32_t *tv = T->tv + 3 * (size_t)star[k];
        int i = tv[0] == v ? 0 : tv[1] == v ? 1 : 2;
        int32_t ia = tv[(i + 1) % 3], ib = tv[(i + 2) % 3];
        const double *a = cvm__tri2_pt(T, ia), *b = cvm__tri2_pt(T, ib);
        double la2, lb2, lab2, la, lb, lab, ar, ls, s[3];
        int j;
        if (cvm__orient2d_inline(p, a, b) <= 0)
            return 0;
        la2 = (a[0] - p[0]) * (a[0] - p[0]) + (a[1] - p[1]) * (a[1] - p[1]);
        lb2 = (b[0] - p[0]) * (b[0] - p[0]) + (b[1] - p[1]) * (b[1] - p[1]);
        lab2 = (b[0] - a[0]) * (b[0] - a[0]) + (b[1] - a[1]) * (b[1] - a[1]);
        la = sqrt(la2);
        lb = sqrt(lb2);
        lab = sqrt(lab2);
        ar = (a[0] - p[0]) * (b[1] - p[1]) - (a[1] - p[1]) * (b[0] - p[0]); /* 2 x area */
        if (!(ar > 0) || !(la > 0) || !(lb > 0))
            return 0;
        s[0] = ar / (la * lb);
        s[1] = ar / (la * lab);
        s[2] = ar / (lb * lab);
        for (j = 0; j < 3; j++) {
            if (s[j] < m)
                m = s[j];
            f[3 * k + (size_t)j] = s[j];
        }
        if (g) {
            /* grad(2 x area) = (a1 - b1, b0 - a0); grad |p - a| = (p - a) / |p - a| */
            double ga0 = (a[1] - b[1]) / ar, ga1 = (b[0] - a[0]) / ar;
            double da0 = (p[0] - a[0]) / la2, da1 = (p[1] - a[1]) / la2;
            double db0 = (p[0] - b[0]) / lb2, db1 = (p[1] - b[1]) / lb2;
            double *gk = g + 6 * k;
            gk[0] = s[0] * (ga0 - da0 - db0);
            gk[1] = s[0] * (ga1 - da1 - db1);
            gk[2] = s[1] * (ga0 - da0);
            gk[3] = s[1] * (ga1 - da1);
            gk[4] = s[2] * (ga0 - db0);
            gk[5] = s[2] * (ga1 - db1);
        }
        ls = (R->vls[v] + R->vls[ia] + R->vls[ib]) / 3;
        if ((isfinite(ls) && la2 * lb2 * lab2 > 4 * R->size2 * ls * ls * ar * ar) ||
            (cvm__rf_max_area(R, star[k]) > 0 && ar > 2 * cvm__rf_max_area(R, star[k])))
            sbig++;
    }
    *fmin = m;
    *big = sbig;
    return 1;
}

cvm_status cvm__rf_smooth_maxmin(cvm__refiner *R, size_t first, const uint8_t *only, int sweeps,
                                 int guard, size_t *moves_out)
{
    /* guard: only stars with an angle below 40 degrees (sin 40) */
    const double fmax = guard ? 0.64278760968653925 : 2.0;
    cvm__tri2 *T = R->T;
    int32_t *star = NULL;
    cvm__sm_ring ring = {0, 0, NULL, NULL, NULL, NULL, 1.0};
    double *f = NULL, *g = NULL, *f1 = NULL;
    size_t *act = NULL;
    uint8_t *cur = NULL, *next = NULL;
    size_t cap = 0, capf = 0, capg = 0, capf1 = 0, capa = 0, v, moves = 0;
    int sweep, err = 0;
    cvm_status s = CVM_OK;
    if (moves_out)
        *moves_out = 0;
    if (sweeps <= 0 || first >= T->nv)
        return CVM_OK;
    cur = cvm__malloc(T->ctx, T->nv);
    next = cvm__malloc(T->ctx, T->nv);
    if (!cur || !next) {
        s = cvm__nomem(T->ctx);
        goto done;
    }
    /* first sweep: the vertices of triangles with an angle outside [55, 65] degrees */
    memset(cur, 0, T->nv);
    if (only)
        cvm__sm_mark_only(T, first, only, 0, cur, next);
    else {
        size_t t;
        for (t = 0; t < T->nt; t++) {
            const int32_t *tv = T->tv + 3 * t;
            if (cvm__tri2_in_domain(T, (int32_t)t) && !cvm__sm_perfect(T, (int32_t)t))
                cur[tv[0]] = cur[tv[1]] = cur[tv[2]] = 1;
        }
    }
    for (sweep = 0; sweep < sweeps; sweep++) {
        size_t moved_before = moves;
        memset(next, 0, T->nv);
        for (v = first; v < T->nv; v++) {
            size_t n, nf, k, na, it;
            double *x = T->xy + 2 * v;
            double p[2], f0, fm, fmin1, lmin = INFINITY;
            int big0, bigm, big1, moved = 0;
            if (!cur[v] || (only && !only[v]))
                continue;
            if ((s = cvm__tick(T->ctx, 1, CVM_STAGE_REFINE, 1.0))) {
                s = cvm__sm_stopped(T->ctx, s);
                goto done;
            }
            n = cvm__sm_star(T, (int32_t)v, &star, &cap, &err);
            if (err)
                break;
            if (n < 3)
                continue;
            nf = 3 * n;
            if ((nf > capf && cvm__grow(T->ctx, (void **)&f, &capf, nf, sizeof *f)) ||
                (nf > capf1 && cvm__grow(T->ctx, (void **)&f1, &capf1, nf, sizeof *f1)) ||
                (2 * nf > capg && cvm__grow(T->ctx, (void **)&g, &capg, 2 * nf, sizeof *g)) ||
                (nf > capa && cvm__grow(T->ctx, (void **)&act, &capa, nf, sizeof *act))) {
                err = 1;
                break;
            }
            p[0] = x[0];
            p[1] = x[1];
            if (!mm_eval(R, (int32_t)v, p, star, n, f, g, &f0, &big0) || f0 >= fmax)
                continue;
            for (k = 0; k < n; k++) {
                const int32_t *tv = T->tv + 3 * (size_t)star[k];
                int i = tv[0] == (int32_t)v ? 0 : tv[1] == (int32_t)v ? 1 : 2;
                const double *a = cvm__tri2_pt(T, tv[(i + 1) % 3]);
                double l = hypot(a[0] - p[0], a[1] - p[1]);
                if (l < lmin)
                    lmin = l;
            }
            fm = f0;
            bigm = big0;
            for (it = 0; it < MM_ITERS; it++) {
                double d[2] = {0, 0}, dd, alpha = INFINITY, amax, q[2], gain;
                int h, ok = 0;
                na = 0;
                for (k = 0; k < nf; k++)
                    if (f[k] <= fm + MM_ACTIVE_TOL)
                        act[na++] = k;
                if (!cvm__minnorm_hull(g, 2, act, na, d))
                    break;
                dd = d[0] * d[0] + d[1] * d[1];
                /* first step at which an inactive function meets the active
                 * ones, to first order (Freitag's step) */
                for (k = 0; k < nf; k++) {
                    double gd = g[2 * k] * d[0] + g[2 * k + 1] * d[1];
                    if (f[k] > fm + MM_ACTIVE_TOL && gd < dd) {
                        double a = (f[k] - fm) / (dd - gd);
                        if (a < alpha)
                            alpha = a;
                    }
                }
                amax = 0.25 * lmin / sqrt(dd); /* never more than a quarter of the shortest spoke */
                if (!(alpha <= amax))
                    alpha = amax;
                for (h = 0; h < MM_HALVINGS; h++, alpha *= 0.5) {
                    q[0] = p[0] + alpha * d[0];
                    q[1] = p[1] + alpha * d[1];
                    if (!isfinite(q[0]) || !isfinite(q[1]))
                        continue;
                    if (mm_eval(R, (int32_t)v, q, star, n, f1, NULL, &fmin1, &big1) &&
                        big1 <= bigm && fmin1 > fm + 1e-12) {
                        ok = 1;
                        break;
                    }
                }
                if (!ok)
                    break;
                p[0] = q[0];
                p[1] = q[1];
                gain = fmin1 - fm;
                if (!mm_eval(R, (int32_t)v, p, star, n, f, g, &fm, &bigm))
                    break; /* cannot happen: p was just accepted */
                moved = 1;
                if (gain < 1e-6 * fm)
                    break; /* improvement has stopped */
            }
            if (!moved || !(fm > f0) || bigm > big0)
                continue;
            if (guard) {
                /* keep the regularity: no more obtuse angles - angles in [55, 65]
                 * (the integer part of cvm__sm_ring_eval's score; the mean-ratio
                 * term of a star is below 0.05) */
                double b0, b1, q0, q1;
                int g0, g1;
                if (!cvm__sm_ring_build(R, (int32_t)v, star, n, &ring)) {
                    err = 1;
                    break;
                }
                if (!cvm__sm_ring_eval(&ring, x, HUGE_VAL, -1.0, INT_MAX, &b0, &q0, &g0) ||
                    !cvm__sm_ring_eval(&ring, p, HUGE_VAL, -1.0, INT_MAX, &b1, &q1, &g1) ||
                    floor(b1 + 0.5) > floor(b0 + 0.5))
                    continue;
            }
            x[0] = p[0];
            x[1] = p[1];
            cvm__sm_moved(T, v, star, n, cur, next);
            moves++;
        }
        if (err || moves == moved_before)
            break;
        {
            uint8_t *sw = cur;
            cur = next;
            next = sw;
        }
    }
    if (err)
        s = cvm__nomem(T->ctx);
done:
    cvm__sm_ring_free(T->ctx, &ring);
    cvm__free(T->ctx, star);
    cvm__free(T->ctx, f);
    cvm__free(T->ctx, f1);
    cvm__free(T->ctx, g);
    cvm__free(T->ctx, act);
    cvm__free(T->ctx, cur);
    cvm__free(T->ctx, next);
    if (moves_out)
        *moves_out = moves;
    return s;
}
