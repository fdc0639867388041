/* smooth_star.c - the star of a vertex as the smoothing passes evaluate it: gathering the star
 * and its ring, the regularity count of a candidate position (floating point screen, exact
 * orientation check), perfect triangles and the marks that choose the vertices of a sweep. */
#include <limits.h>
#include <math.h>
#include <string.h>

#include "smooth.h"
#include "delaunay/tri2_store.h"
#include "geom/geom_internal.h"

/* Star of v into *star (triangles, counter-clockwise); returns the count, or 0
 * when v may not move: a star triangle outside the domain or a constrained
 * spoke edge. *err is set on NOMEM. */
size_t cvm__sm_star(const cvm__tri2 *T, int32_t v, int32_t **star, size_t *cap, int *err)
{
    int32_t t0 = T->vtri[v], t = t0;
    size_t n = 0;
    if (t0 < 0)
        return 0;
    do {
        const int32_t *tv = T->tv + 3 * (size_t)t;
        int i = tv[0] == v ? 0 : tv[1] == v ? 1 : 2;
        if (!cvm__tri2_in_domain(T, t) || cvm__tri2_edge_seg(T, t, (i + 1) % 3) >= 0 ||
            cvm__tri2_edge_seg(T, t, (i + 2) % 3) >= 0)
            return 0;
        if (n >= *cap && cvm__grow(T->ctx, (void **)star, cap, n + 1, sizeof **star)) {
            *err = 1;
            return 0;
        }
        (*star)[n++] = t;
        t = T->tn[3 * (size_t)t + (i + 1) % 3] / 3;
    } while (t != t0 && n <= T->nt);
    return t == t0 ? n : 0;
}


void cvm__sm_ring_free(cvm__ctx *ctx, cvm__sm_ring *r)
{
    cvm__free(ctx, r->a);
    cvm__free(ctx, r->lab);
    cvm__free(ctx, r->ls4);
    cvm__free(ctx, r->amax2);
}

/* Fill r from the star of v; returns 0 on NOMEM. */
int cvm__sm_ring_build(const cvm__refiner *R, int32_t v, const int32_t *star, size_t n,
                       cvm__sm_ring *r)
{
    const cvm__tri2 *T = R->T;
    size_t k;
    if (n > r->cap) {
        size_t c2 = r->cap, c1 = r->cap, c3 = r->cap, c4 = r->cap;
        if (cvm__grow(T->ctx, (void **)&r->a, &c1, 2 * n, sizeof *r->a) ||
            cvm__grow(T->ctx, (void **)&r->lab, &c2, n, sizeof *r->lab) ||
            cvm__grow(T->ctx, (void **)&r->ls4, &c3, n, sizeof *r->ls4) ||
            cvm__grow(T->ctx, (void **)&r->amax2, &c4, n, sizeof *r->amax2))
            return 0;
        r->cap = n;
    }
    r->n = n;
    r->size2 = R->size2;
    for (k = 0; k < n; k++) {
        const int32_t *tv = T->tv + 3 * (size_t)star[k];
        int i = tv[0] == v ? 0 : tv[1] == v ? 1 : 2;
        int32_t ia = tv[(i + 1) % 3], ib = tv[(i + 2) % 3];
        const double *a = cvm__tri2_pt(T, ia), *b = cvm__tri2_pt(T, ib);
        double ls = (R->vls[v] + R->vls[ia] + R->vls[ib]) / 3, am = cvm__rf_max_area(R, star[k]);
        r->a[2 * k] = a[0];
        r->a[2 * k + 1] = a[1];
        r->lab[k] = (b[0] - a[0]) * (b[0] - a[0]) + (b[1] - a[1]) * (b[1] - a[1]);
        r->ls4[k] = isfinite(ls) ? 4 * R->size2 * ls * ls : HUGE_VAL;
        r->amax2[k] = am > 0 ? 2 * am : 0;
    }
    return 1;
}

/* Regularity of the star of v (gathered in r) with v at p: *bad (lower is
 * better) = SM_OBTUSE_WEIGHT x obtuse angles - angles in [55, 65] degrees + 1e-3 x the sum
 * of (1 - mean ratio); *q = smallest sin^2; *big = triangles above the size
 * bound (circumradius above the mean size, or the area bound). Returns 0 when
 * a triangle is not strictly counter-clockwise (exact orient2d), or as soon
 * as *bad is sure to end >= cut (HUGE_VAL: the full count).
 * A candidate (qmin >= 0) is also rejected (0) as soon as a triangle has an
 * angle whose sin^2 is below qmin or more than bigmax triangles exceed the
 * size bound; *q is then not computed. Orientation is screened in floating
 * point here (a candidate whose doubled area is not positive is rejected);
 * a move is made only after cvm__sm_ring_exact. */
int cvm__sm_ring_eval(const cvm__sm_ring *r, const double *p, double cut, double qmin, int bigmax,
                      double *bad, double *q, int *big)
{
    const double lo2 = 0.42261826174069944 * 0.42261826174069944;
    const double hi2 = 0.57357643635104616 * 0.57357643635104616;
    size_t k, n = r->n;
    double smr = 0, sq = 1.0, lpa, lp0;
    int sbig = 0, nobt = 0, nreg = 0;
    lp0 = lpa = (r->a[0] - p[0]) * (r->a[0] - p[0]) + (r->a[1] - p[1]) * (r->a[1] - p[1]);
    for (k = 0; k < n; k++) {
        const double *a = r->a + 2 * k, *b = r->a + 2 * (k + 1 < n ? k + 1 : 0);
        double lpb = k + 1 < n ? (b[0] - p[0]) * (b[0] - p[0]) + (b[1] - p[1]) * (b[1] - p[1]) : lp0;
        double lab = r->lab[k], ar, num[3], den[3], s, lmin;
        int j;
        ar = (a[0] - p[0]) * (b[1] - p[1]) - (a[1] - p[1]) * (b[0] - p[0]); /* 2 x area */
        if (!(ar > 0))
            return 0;
        num[0] = lpa + lpb - lab;
        den[0] = 4 * lpa * lpb;
        num[1] = lpa + lab - lpb;
        den[1] = 4 * lpa * lab;
        num[2] = lpb + lab - lpa;
        den[2] = 4 * lpb * lab;
        for (j = 0; j < 3; j++) {
            double n2 = num[j] * num[j];
            nobt += num[j] < 0;
            nreg += (num[j] >= 0) & (n2 >= lo2 * den[j]) & (n2 <= hi2 * den[j]);
        }
        /* the rest of the star adds at least -3 per triangle and a positive
         * mean-ratio term: tested before the other terms of this triangle */
        if (SM_OBTUSE_WEIGHT * nobt - nreg - 3 * (int)(n - k - 1) + smr >= cut)
            return 0;
        smr += 1e-3 * (1 - 2 * 1.7320508075688772 * ar / (lpa + lpb + lab));
        lmin = lpa < lpb ? (lpa < lab ? lpa : lab) : (lpb < lab ? lpb : lab);
        if (qmin >= 0) {
            if (lmin * ar * ar < qmin * (lpa * lpb * lab))
                return 0;
        } else {
            s = lmin * ar * ar / (lpa * lpb * lab);
            if (s < sq)
                sq = s;
        }
        if ((lpa * lpb * lab > r->ls4[k] * ar * ar || (r->amax2[k] > 0 && ar > r->amax2[k])) &&
            ++sbig > bigmax)
            return 0;
        lpa = lpb;
    }
    *bad = SM_OBTUSE_WEIGHT * nobt - nreg + smr;
    *q = sq;
    *big = sbig;
    return 1;
}

/* 1 when every star triangle of r is strictly counter-clockwise with the
 * vertex at p (exact orient2d): cvm__sm_ring_eval screens candidates in floating
 * point, a move is made only after this test. */
int cvm__sm_ring_exact(const cvm__sm_ring *r, const double *p)
{
    size_t k, n = r->n;
    for (k = 0; k < n; k++)
        if (cvm__orient2d_inline(p, r->a + 2 * k, r->a + 2 * (k + 1 < n ? k + 1 : 0)) <= 0)
            return 0;
    return 1;
}

/* 1 when every angle of the triangle with squared sides lpa = |pa|^2, lpb =
 * |pb|^2, lab = |ab|^2 is in [55, 65] degrees (the test of cvm__sm_ring_eval:
 * cos^2 of each angle between cos^2 65 and cos^2 55, and no obtuse one). */
int cvm__sm_sides_regular(double lpa, double lpb, double lab)
{
    const double lo2 = 0.42261826174069944 * 0.42261826174069944;
    const double hi2 = 0.57357643635104616 * 0.57357643635104616;
    double num[3], den[3];
    int j;
    num[0] = lpa + lpb - lab;
    den[0] = 4 * lpa * lpb;
    num[1] = lpa + lab - lpb;
    den[1] = 4 * lpa * lab;
    num[2] = lpb + lab - lpa;
    den[2] = 4 * lpb * lab;
    for (j = 0; j < 3; j++)
        if (!(num[j] >= 0 && num[j] * num[j] >= lo2 * den[j] && num[j] * num[j] <= hi2 * den[j]))
            return 0;
    return 1;
}

double cvm__sm_d2(const double *a, const double *b)
{
    return (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]);
}

/* 1 when every angle of domain triangle t is in [55, 65] degrees. */
int cvm__sm_perfect(const cvm__tri2 *T, int32_t t)
{
    const int32_t *tv = T->tv + 3 * (size_t)t;
    const double *p = cvm__tri2_pt(T, tv[0]), *a = cvm__tri2_pt(T, tv[1]), *b = cvm__tri2_pt(T, tv[2]);
    return cvm__sm_sides_regular(cvm__sm_d2(a, p), cvm__sm_d2(b, p),
                                 cvm__sm_d2(b, a));
}

/* 1 when every triangle of star[0..n-1] is perfect (cvm__sm_perfect). */
int cvm__sm_all_perfect(const cvm__tri2 *T, const int32_t *star, size_t n)
{
    size_t k;
    for (k = 0; k < n; k++)
        if (!cvm__sm_perfect(T, star[k]))
            return 0;
    return 1;
}

/* Mark v and its neighbours (the vertices of its star) in mark[]. */
static void sm_mark_star(const cvm__tri2 *T, int32_t v, const int32_t *star, size_t n,
                         uint8_t *mark)
{
    size_t k;
    mark[v] = 1;
    for (k = 0; k < n; k++) {
        const int32_t *tv = T->tv + 3 * (size_t)star[k];
        mark[tv[0]] = mark[tv[1]] = mark[tv[2]] = 1;
    }
}

/* Vertex v moved: its star's vertices are revisited in the next sweep, and
 * those after v in this one. */
void cvm__sm_moved(const cvm__tri2 *T, size_t v, const int32_t *star, size_t n, uint8_t *cur,
                   uint8_t *next)
{
    size_t k;
    sm_mark_star(T, (int32_t)v, star, n, next);
    for (k = 0; k < n; k++) {
        const int32_t *tv = T->tv + 3 * (size_t)star[k];
        cur[tv[0]] = cur[tv[0]] || (size_t)tv[0] > v;
        cur[tv[1]] = cur[tv[1]] || (size_t)tv[1] > v;
        cur[tv[2]] = cur[tv[2]] || (size_t)tv[2] > v;
    }
}

/* Mark in cur the vertices of domain triangles with an angle outside [55, 65]
 * degrees (the others are left alone by the smart rule anyway). */
void cvm__sm_mark_imperfect(const cvm__tri2 *T, uint8_t *cur)
{
    size_t t;
    memset(cur, 0, T->nv);
    for (t = 0; t < T->nt; t++) {
        const int32_t *tv = T->tv + 3 * t;
        if (cvm__tri2_in_domain(T, (int32_t)t) && !cvm__sm_perfect(T, (int32_t)t))
            cur[tv[0]] = cur[tv[1]] = cur[tv[2]] = 1;
    }
}

/* 1 when a domain triangle at v has an angle outside [55, 65] degrees;
 * memo (NULL or per vertex: 0 unknown, 1 no, 2 yes) keeps the answers. */
static int sm_star_imperfect(const cvm__tri2 *T, int32_t v, uint8_t *memo)
{
    int32_t t0 = T->vtri[v], t = t0;
    size_t n = 0;
    int r = 0;
    if (memo && memo[v])
        return memo[v] == 2;
    if (t0 < 0)
        return 0;
    do {
        if (cvm__tri2_in_domain(T, t) && !cvm__sm_perfect(T, t)) {
            r = 1;
            break;
        }
        t = cvm__tri2_around(T, t, v);
    } while (t != t0 && ++n <= T->nt);
    if (memo)
        memo[v] = (uint8_t)(r + 1);
    return r;
}

/* The first marks when only the vertices v >= first with only[v] may move:
 * cvm__sm_mark_imperfect (then cvm__sm_dilate when dilate is set) restricted to them,
 * from their stars instead of a scan of every triangle; tmp is scratch of
 * T->nv bytes. */
void cvm__sm_mark_only(const cvm__tri2 *T, size_t first, const uint8_t *only, int dilate,
                       uint8_t *cur, uint8_t *tmp)
{
    size_t v;
    memset(cur, 0, T->nv);
    memset(tmp, 0, T->nv);
    for (v = first; v < T->nv; v++) {
        int32_t t0, t;
        size_t n = 0;
        if (!only[v] || (t0 = T->vtri[v]) < 0)
            continue;
        cur[v] = (uint8_t)sm_star_imperfect(T, (int32_t)v, tmp);
        if (cur[v] || !dilate)
            continue;
        /* dilated: a vertex of a domain triangle at v is marked */
        t = t0;
        do {
            const int32_t *tv = T->tv + 3 * (size_t)t;
            int i = cvm__tri2_corner(T, t, (int32_t)v);
            if (cvm__tri2_in_domain(T, t) &&
                (sm_star_imperfect(T, tv[(i + 1) % 3], tmp) ||
                 sm_star_imperfect(T, tv[(i + 2) % 3], tmp))) {
                cur[v] = 1;
                break;
            }
            t = T->tn[3 * (size_t)t + (i + 1) % 3] / 3;
        } while (t != t0 && ++n <= T->nt);
    }
}

/* Add to cur every vertex sharing a domain triangle with a marked one; tmp
 * is scratch of T->nv bytes. */
void cvm__sm_dilate(const cvm__tri2 *T, uint8_t *cur, uint8_t *tmp)
{
    size_t t;
    memcpy(tmp, cur, T->nv);
    for (t = 0; t < T->nt; t++) {
        const int32_t *tv = T->tv + 3 * t;
        if (cvm__tri2_in_domain(T, (int32_t)t) && (tmp[tv[0]] || tmp[tv[1]] || tmp[tv[2]]))
            cur[tv[0]] = cur[tv[1]] = cur[tv[2]] = 1;
    }
}

cvm_status cvm__sm_stopped(cvm__ctx *ctx, cvm_status s)
{
    return cvm__error(ctx, s, CVM_ENT_NONE, -1,
                      "refinement %s while smoothing; the mesh is valid but some triangles may "
                      "not meet the bounds",
                      s == CVM_INCOMPLETE_CANCELLED ? "was cancelled" : "reached the time limit");
}
