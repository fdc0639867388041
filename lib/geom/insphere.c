/* insphere.c - exact 3D in-sphere test: filter, exact stage B, then an exact expansion. */
#include <math.h>

#include "geom/exact_det.h"
#include "geom/expansion.h"
#include "geom/geom_internal.h"

/* Shewchuk's isperrboundB (A is cvm__isp_errbound_a in geom_internal.h). */
static const double isp_errbound_b = (5.0 + 72.0 * CVM__EPS) * CVM__EPS;

/*
 * With p.e = p - e and plift = |p - e|^2, the determinant is
 * det [aex aey aez alift; ...; dex dey dez dlift]
 *   = dlift abc - clift dab + blift cda - alift bcd,
 * where pqr = det [p; q; r] of the translated xyz rows, expanded along z from
 * the xy minors pq = pex qey - qex pey.
 */

/* The xy minor p.x q.y - q.x p.y, at most 4 components. */
typedef struct {
    int n;
    double h[4];
} insphere_minor;

static void insphere_cross(const double *p, const double *q, insphere_minor *m)
{
    m->n = cvm__cross_zeroelim(p[0], q[1], q[0], p[1], m->h);
}

/* out = z0 m0 + z1 m1 + z2 m2 exactly; length <= 24. */
static int insphere_det3(const insphere_minor *m0, double z0, const insphere_minor *m1, double z1,
                         const insphere_minor *m2, double z2, double *out)
{
    double t0[8], t1[8], t2[8], s[16];
    int n0 = cvm__scale_expansion_zeroelim(m0->n, m0->h, z0, t0);
    int n1 = cvm__scale_expansion_zeroelim(m1->n, m1->h, z1, t1);
    int n2 = cvm__scale_expansion_zeroelim(m2->n, m2->h, z2, t2);
    int ns = cvm__fast_expansion_sum_zeroelim(n0, t0, n1, t1, s);
    return cvm__fast_expansion_sum_zeroelim(ns, s, n2, t2, out);
}

/* Stage B, then the exact expansion, on inputs already in the safe range. */
static double insphere_stages(const double *pa, const double *pb, const double *pc,
                              const double *pd, const double *pe)
{
    double a[3], b[3], c[3], d[3];
    insphere_minor ab, bc, cd, da, ac, bd;
    double abc[24], bcd[24], cda[24], dab[24], t[4][288], s[2][576], fin[1152];
    double permanent, det, errbound;
    int i, nabc, nbcd, ncda, ndab, n[4], m0, m1, fn;

    for (i = 0; i < 3; i++) {
        a[i] = pa[i] - pe[i], b[i] = pb[i] - pe[i];
        c[i] = pc[i] - pe[i], d[i] = pd[i] - pe[i];
    }
    insphere_cross(a, b, &ab);
    insphere_cross(b, c, &bc);
    insphere_cross(c, d, &cd);
    insphere_cross(d, a, &da);
    insphere_cross(a, c, &ac);
    insphere_cross(b, d, &bd);
    nabc = insphere_det3(&bc, a[2], &ac, -b[2], &ab, c[2], abc);
    nbcd = insphere_det3(&cd, b[2], &bd, -c[2], &bc, d[2], bcd);
    ncda = insphere_det3(&da, c[2], &ac, d[2], &cd, a[2], cda);
    ndab = insphere_det3(&ab, d[2], &bd, a[2], &da, b[2], dab);
    n[0] = cvm__lift_scale(nabc, abc, d, 3, 0.0, 1.0, t[0]);
    n[1] = cvm__lift_scale(ndab, dab, c, 3, 0.0, -1.0, t[1]);
    n[2] = cvm__lift_scale(ncda, cda, b, 3, 0.0, 1.0, t[2]);
    n[3] = cvm__lift_scale(nbcd, bcd, a, 3, 0.0, -1.0, t[3]);
    m0 = cvm__fast_expansion_sum_zeroelim(n[0], t[0], n[1], t[1], s[0]);
    m1 = cvm__fast_expansion_sum_zeroelim(n[2], t[2], n[3], t[3], s[1]);
    fn = cvm__fast_expansion_sum_zeroelim(m0, s[0], m1, s[1], fin);
    det = cvm__estimate(fn, fin);

    permanent = (fabs(a[2]) * (fabs(b[0] * c[1]) + fabs(c[0] * b[1]))
                 + fabs(b[2]) * (fabs(a[0] * c[1]) + fabs(c[0] * a[1]))
                 + fabs(c[2]) * (fabs(a[0] * b[1]) + fabs(b[0] * a[1])))
                    * (d[0] * d[0] + d[1] * d[1] + d[2] * d[2])
                + (fabs(d[2]) * (fabs(a[0] * b[1]) + fabs(b[0] * a[1]))
                   + fabs(a[2]) * (fabs(b[0] * d[1]) + fabs(d[0] * b[1]))
                   + fabs(b[2]) * (fabs(d[0] * a[1]) + fabs(a[0] * d[1])))
                      * (c[0] * c[0] + c[1] * c[1] + c[2] * c[2])
                + (fabs(c[2]) * (fabs(d[0] * a[1]) + fabs(a[0] * d[1]))
                   + fabs(d[2]) * (fabs(a[0] * c[1]) + fabs(c[0] * a[1]))
                   + fabs(a[2]) * (fabs(c[0] * d[1]) + fabs(d[0] * c[1])))
                      * (b[0] * b[0] + b[1] * b[1] + b[2] * b[2])
                + (fabs(b[2]) * (fabs(c[0] * d[1]) + fabs(d[0] * c[1]))
                   + fabs(c[2]) * (fabs(b[0] * d[1]) + fabs(d[0] * b[1]))
                   + fabs(d[2]) * (fabs(b[0] * c[1]) + fabs(c[0] * b[1])))
                      * (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    errbound = isp_errbound_b * permanent;
    if (det >= errbound || -det >= errbound)
        return det;
    for (i = 0; i < 3; i++) {
        if (cvm__two_diff_tail(pa[i], pe[i], a[i]) != 0.0
            || cvm__two_diff_tail(pb[i], pe[i], b[i]) != 0.0
            || cvm__two_diff_tail(pc[i], pe[i], c[i]) != 0.0
            || cvm__two_diff_tail(pd[i], pe[i], d[i]) != 0.0)
            return cvm__insphere_exact(pa, pb, pc, pd, pe);
    }
    return det; /* every difference was exact, so B was the exact value */
}

CVM__NOINLINE double cvm__insphere_adapt(const double *a, const double *b, const double *c,
                                         const double *d, const double *e)
{
    const double *p[5];
    double s[5][3], m = 0.0;
    int i, j, k;
    p[0] = a, p[1] = b, p[2] = c, p[3] = d, p[4] = e;
    for (i = 0; i < 5; i++)
        for (j = 0; j < 3; j++)
            m = cvm__maxabs(m, p[i][j]);
    k = cvm__rescale_exponent(m);
    if (k == 0)
        return insphere_stages(a, b, c, d, e);
    for (i = 0; i < 5; i++)
        for (j = 0; j < 3; j++)
            s[i][j] = ldexp(p[i][j], k);
    return cvm__unscale(insphere_stages(s[0], s[1], s[2], s[3], s[4]), 5, k);
}

double cvm__insphere(const double *a, const double *b, const double *c, const double *d,
                     const double *e)
{
    double permanent, det = cvm__insphere_fp(a, b, c, d, e, &permanent);
    if (fabs(det) > cvm__isp_errbound_a * permanent + cvm__filter_floor)
        return det;
    return cvm__insphere_adapt(a, b, c, d, e);
}

/* The 5x5 determinant [x y z |x|^2 1] expanded along the lifted column:
 * -lift(a) Q(b,c,d,e) + lift(b) Q(a,c,d,e) - lift(c) Q(a,b,d,e)
 * + lift(d) Q(a,b,c,e) - lift(e) Q(a,b,c,d), Q the raw orient3d. About 120 KB
 * of stack, only ever reached for nearly cospherical inputs. */
CVM__NOINLINE double cvm__insphere_exact(const double *a, const double *b, const double *c,
                                         const double *d, const double *e)
{
    const double *p[5];
    const double *rest[4];
    double q[96], term[1152], acc[2][5760];
    int i, j, r, qn, tn, n = 0, cur = 0;
    p[0] = a, p[1] = b, p[2] = c, p[3] = d, p[4] = e;
    for (i = 0; i < 5; i++) {
        for (j = 0, r = 0; j < 5; j++)
            if (j != i)
                rest[r++] = p[j];
        qn = cvm__orient3d_raw(rest[0], rest[1], rest[2], rest[3], q);
        tn = cvm__lift_scale(qn, q, p[i], 3, 0.0, (i % 2 == 0) ? -1.0 : 1.0, term);
        if (i == 0) {
            for (j = 0; j < tn; j++)
                acc[0][j] = term[j];
            n = tn;
        } else {
            n = cvm__fast_expansion_sum_zeroelim(n, acc[cur], tn, term, acc[1 - cur]);
            cur = 1 - cur;
        }
    }
    return acc[cur][n - 1];
}
